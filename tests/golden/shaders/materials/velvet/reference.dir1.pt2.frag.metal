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
    float _784 = _619.y;
    float _789 = _619.z;
    float _794 = _619.x;
    float _900 = fast::max(dot(_619, _625), 9.9999997473787516355514526367188e-05);
    float4 _905 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_900, params.facet_perceptualRoughness), level(0.0));
    float _908 = _905.w;
    float3 _941 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _982 = dot(_619, frame.lightDirection.xyz);
    float _984 = fast::clamp(_982, 0.0, 1.0);
    float _988 = fast::clamp(dot(_619, fast::normalize(_625 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1067 = 2.0 + (1.0 / params.facet_alpha);
    float _1070 = 0.5 / params.facet_alpha;
    float3 _1096 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _784)) + (frame.sh[2].xyz * _789)) + (frame.sh[3].xyz * _794)) + (((((frame.sh[4].xyz * (_794 * _784)) + (frame.sh[5].xyz * (_784 * _789))) + (frame.sh[6].xyz * fma(3.0 * _789, _789, -1.0))) + (frame.sh[7].xyz * (_794 * _789))) + (frame.sh[8].xyz * fma(_794, _794, -(_784 * _784)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_625, _619), level(params.facet_perceptualRoughness * 4.0)).xyz * (_941 * _905.z)) + fast::min(fma(float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_982 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0)), fast::clamp(float3(params.subsurface) + float3(_984), float3(0.0), float3(1.0)), _941 * ((((_1067 * pow(fast::max(fma(-_988, _988, 1.0), 0.0), _1070)) * 0.15915493667125701904296875) * (_984 / (4.0 * fma(-_984, _900, _984 + _900)))) * _908)) * frame.lightColor.xyz, float3(65504.0));
    float3 _1131 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1134 = dot(_1131, _1131);
    float3 _1139 = _1131 * rsqrt(fast::max(_1134, 9.9999999392252902907785028219223e-09));
    float _1143 = _1134 * float(frame.punctualLights[0].positionFalloff.w);
    float _1148 = fast::clamp(fma(-_1143, _1143, 1.0), 0.0, 1.0);
    float _1167 = fast::clamp(fma(dot(-_1139, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1212 = dot(_619, _1139);
    float _1214 = fast::clamp(_1212, 0.0, 1.0);
    float _1218 = fast::clamp(dot(_619, fast::normalize(_625 + _1139)), 0.0, 1.0);
    float3 _1361 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1364 = dot(_1361, _1361);
    float3 _1369 = _1361 * rsqrt(fast::max(_1364, 9.9999999392252902907785028219223e-09));
    float _1373 = _1364 * float(frame.punctualLights[1].positionFalloff.w);
    float _1378 = fast::clamp(fma(-_1373, _1373, 1.0), 0.0, 1.0);
    float _1397 = fast::clamp(fma(dot(-_1369, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1442 = dot(_619, _1369);
    float _1444 = fast::clamp(_1442, 0.0, 1.0);
    float _1448 = fast::clamp(dot(_619, fast::normalize(_625 + _1369)), 0.0, 1.0);
    float3 _1556 = (_1096 + fast::min(fma(float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1212 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0)), fast::clamp(float3(params.subsurface) + float3(_1214), float3(0.0), float3(1.0)), _941 * ((((_1067 * pow(fast::max(fma(-_1218, _1218, 1.0), 0.0), _1070)) * 0.15915493667125701904296875) * (_1214 / (4.0 * fma(-_1214, _900, _1214 + _900)))) * _908)) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1148 * _1148) / fast::max(_1134, 9.9999997473787516355514526367188e-05)) * _1167) * _1167)), float3(65504.0))) + fast::min(fma(float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1442 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0)), fast::clamp(float3(params.subsurface) + float3(_1444), float3(0.0), float3(1.0)), _941 * ((((_1067 * pow(fast::max(fma(-_1448, _1448, 1.0), 0.0), _1070)) * 0.15915493667125701904296875) * (_1444 / (4.0 * fma(-_1444, _900, _1444 + _900)))) * _908)) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1378 * _1378) / fast::max(_1364, 9.9999997473787516355514526367188e-05)) * _1397) * _1397)), float3(65504.0));
    out.fragColor = float4(_1556, 1.0);
    return out;
}

