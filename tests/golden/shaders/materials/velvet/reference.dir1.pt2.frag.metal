#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
};

struct PunctualLightData
{
    float4 positionFalloff;
    float4 colorIntensity;
    float4 direction;
    float4 spotScaleOffset;
};

struct FrameUniforms
{
    float4x4 viewProjection;
    float4 cameraPosition;
    float4 lightDirection;
    float4 lightColor;
    float4 ambient;
    PunctualLightData punctualLights[4];
    float4 sh[9];
};

struct main0_out
{
    float4 fragColor [[color(0)]];
};

struct main0_in
{
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _636 = fast::normalize(in.v_normal);
    float3 _642 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _799 = _636.y;
    float _804 = _636.z;
    float _809 = _636.x;
    float _917 = fast::max(dot(_636, _642), 9.9999997473787516355514526367188e-05);
    float4 _922 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_917, params.facet_perceptualRoughness), level(0.0));
    float3 _968 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _935 = _922.z;
    float _937 = fma(-fast::max(_968.x, fast::max(_968.y, _968.z)), _935, 1.0);
    float _939 = _922.w;
    float _1002 = dot(_636, frame.lightDirection.xyz);
    float _1004 = fast::clamp(_1002, 0.0, 1.0);
    float _1018 = fast::clamp(dot(_636, fast::normalize(_642 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1089 = 8192.0 * fma(-_1004, _917, _1004 + _917);
    float _1093 = 1.0 / (params.facet_alpha * _1089);
    float _1100 = 2048.0 * params.facet_alpha;
    float3 _1128 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_642, _636), level(params.facet_perceptualRoughness * 4.0)).xyz, _968 * _935, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _799)) + (frame.sh[2].xyz * _804)) + (frame.sh[3].xyz * _809)) + (((((frame.sh[4].xyz * (_809 * _799)) + (frame.sh[5].xyz * (_799 * _804))) + (frame.sh[6].xyz * fma(3.0 * _804, _804, -1.0))) + (frame.sh[7].xyz * (_809 * _804))) + (frame.sh[8].xyz * fma(_809, _809, -(_799 * _799)))), float3(0.0))) * _937) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1002 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1004), float3(0.0), float3(1.0))) * _937) + (_968 * ((((fma(_1093, _1089, 2.0) * pow(fast::max(fma(-_1018, _1018, 1.0), 0.0), 0.5 * (_1093 * _1089))) * 0.15915493667125701904296875) * (_1004 * (_1093 * _1100))) * _939))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1163 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1166 = dot(_1163, _1163);
    float3 _1171 = _1163 * rsqrt(fast::max(_1166, 9.9999999392252902907785028219223e-09));
    float _1175 = _1166 * float(frame.punctualLights[0].positionFalloff.w);
    float _1180 = fast::clamp(fma(-_1175, _1175, 1.0), 0.0, 1.0);
    float _1199 = fast::clamp(fma(dot(-_1171, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1234 = dot(_636, _1171);
    float _1236 = fast::clamp(_1234, 0.0, 1.0);
    float _1250 = fast::clamp(dot(_636, fast::normalize(_642 + _1171)), 0.0, 1.0);
    float _1321 = 8192.0 * fma(-_1236, _917, _1236 + _917);
    float _1325 = 1.0 / (params.facet_alpha * _1321);
    float3 _1395 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1398 = dot(_1395, _1395);
    float3 _1403 = _1395 * rsqrt(fast::max(_1398, 9.9999999392252902907785028219223e-09));
    float _1407 = _1398 * float(frame.punctualLights[1].positionFalloff.w);
    float _1412 = fast::clamp(fma(-_1407, _1407, 1.0), 0.0, 1.0);
    float _1431 = fast::clamp(fma(dot(-_1403, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1466 = dot(_636, _1403);
    float _1468 = fast::clamp(_1466, 0.0, 1.0);
    float _1482 = fast::clamp(dot(_636, fast::normalize(_642 + _1403)), 0.0, 1.0);
    float _1553 = 8192.0 * fma(-_1468, _917, _1468 + _917);
    float _1557 = 1.0 / (params.facet_alpha * _1553);
    float3 _1592 = (_1128 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1234 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1236), float3(0.0), float3(1.0))) * _937) + (_968 * ((((fma(_1325, _1321, 2.0) * pow(fast::max(fma(-_1250, _1250, 1.0), 0.0), 0.5 * (_1325 * _1321))) * 0.15915493667125701904296875) * (_1236 * (_1325 * _1100))) * _939))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1180 * _1180) / fast::max(_1166, 9.9999997473787516355514526367188e-05)) * _1199) * _1199)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1466 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1468), float3(0.0), float3(1.0))) * _937) + (_968 * ((((fma(_1557, _1553, 2.0) * pow(fast::max(fma(-_1482, _1482, 1.0), 0.0), 0.5 * (_1557 * _1553))) * 0.15915493667125701904296875) * (_1468 * (_1557 * _1100))) * _939))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1412 * _1412) / fast::max(_1398, 9.9999997473787516355514526367188e-05)) * _1431) * _1431)), float3(65504.0));
    out.fragColor = float4(_1592, 1.0);
    return out;
}

