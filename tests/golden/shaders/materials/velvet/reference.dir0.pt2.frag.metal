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
    float3 _619 = fast::normalize(in.v_normal);
    float3 _625 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _763 = _619.y;
    float _768 = _619.z;
    float _773 = _619.x;
    float _879 = fast::max(dot(_619, _625), 9.9999997473787516355514526367188e-05);
    float4 _884 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_879, params.facet_perceptualRoughness), level(0.0));
    float _887 = _884.w;
    float3 _920 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float3 _960 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _963 = dot(_960, _960);
    float3 _968 = _960 * rsqrt(fast::max(_963, 9.9999999392252902907785028219223e-09));
    float _972 = _963 * float(frame.punctualLights[0].positionFalloff.w);
    float _977 = fast::clamp(fma(-_972, _972, 1.0), 0.0, 1.0);
    float _996 = fast::clamp(fma(dot(-_968, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1041 = dot(_619, _968);
    float _1043 = fast::clamp(_1041, 0.0, 1.0);
    float _1047 = fast::clamp(dot(_619, fast::normalize(_625 + _968)), 0.0, 1.0);
    float _1126 = 2.0 + (1.0 / params.facet_alpha);
    float _1129 = 0.5 / params.facet_alpha;
    float3 _1155 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _763)) + (frame.sh[2].xyz * _768)) + (frame.sh[3].xyz * _773)) + (((((frame.sh[4].xyz * (_773 * _763)) + (frame.sh[5].xyz * (_763 * _768))) + (frame.sh[6].xyz * fma(3.0 * _768, _768, -1.0))) + (frame.sh[7].xyz * (_773 * _768))) + (frame.sh[8].xyz * fma(_773, _773, -(_763 * _763)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_625, _619), level(params.facet_perceptualRoughness * 4.0)).xyz * (_920 * _884.z)) + fast::min(fma(float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1041 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0)), fast::clamp(float3(params.subsurface) + float3(_1043), float3(0.0), float3(1.0)), _920 * ((((_1126 * pow(fast::max(fma(-_1047, _1047, 1.0), 0.0), _1129)) * 0.15915493667125701904296875) * (_1043 / (4.0 * fma(-_1043, _879, _1043 + _879)))) * _887)) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_977 * _977) / fast::max(_963, 9.9999997473787516355514526367188e-05)) * _996) * _996)), float3(65504.0));
    float3 _1190 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1193 = dot(_1190, _1190);
    float3 _1198 = _1190 * rsqrt(fast::max(_1193, 9.9999999392252902907785028219223e-09));
    float _1202 = _1193 * float(frame.punctualLights[1].positionFalloff.w);
    float _1207 = fast::clamp(fma(-_1202, _1202, 1.0), 0.0, 1.0);
    float _1226 = fast::clamp(fma(dot(-_1198, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1271 = dot(_619, _1198);
    float _1273 = fast::clamp(_1271, 0.0, 1.0);
    float _1277 = fast::clamp(dot(_619, fast::normalize(_625 + _1198)), 0.0, 1.0);
    out.fragColor = float4(_1155 + fast::min(fma(float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1271 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0)), fast::clamp(float3(params.subsurface) + float3(_1273), float3(0.0), float3(1.0)), _920 * ((((_1126 * pow(fast::max(fma(-_1277, _1277, 1.0), 0.0), _1129)) * 0.15915493667125701904296875) * (_1273 / (4.0 * fma(-_1273, _879, _1273 + _879)))) * _887)) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1207 * _1207) / fast::max(_1193, 9.9999997473787516355514526367188e-05)) * _1226) * _1226)), float3(65504.0)), 1.0);
    return out;
}

