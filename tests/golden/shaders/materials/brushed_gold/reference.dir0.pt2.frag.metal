#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
    packed_float3 facet_f0;
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
    float3 _774 = fast::normalize(in.v_normal);
    float3 _780 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1047 = fast::max(dot(_774, _780), 9.9999997473787516355514526367188e-05);
    float4 _1086 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1047, params.facet_perceptualRoughness), level(0.0));
    float3 _1105 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1086.y) - 1.0));
    float3 _1156 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1159 = dot(_1156, _1156);
    float3 _1164 = _1156 * rsqrt(fast::max(_1159, 9.9999999392252902907785028219223e-09));
    float _1168 = _1159 * float(frame.punctualLights[0].positionFalloff.w);
    float _1173 = fast::clamp(fma(-_1168, _1168, 1.0), 0.0, 1.0);
    float _1192 = fast::clamp(fma(dot(-_1164, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1307 = fast::normalize(_780 + _1164);
    float _1252 = fast::clamp(dot(_774, _1164), 0.0, 1.0);
    float _1345 = 4096.0 * params.facet_alpha;
    float4 _1369 = float4(cross(_774, _1307), params.facet_alpha * fast::clamp(dot(_774, _1307), 0.0, 1.0)) * 64.0;
    float _1351 = _1345 / dot(_1369, _1369);
    float _1380 = params.facet_alpha * params.facet_alpha;
    float _1386 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1390 = sqrt(fma(_1047 * _1047, _1386, _1380));
    float _1413 = 1.0 - fast::clamp(dot(_1164, _1307), 0.0, 1.0);
    float _1416 = _1413 * _1413;
    float3 _1424 = float3(1.0) - float3(params.facet_f0);
    float3 _1481 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1484 = dot(_1481, _1481);
    float3 _1489 = _1481 * rsqrt(fast::max(_1484, 9.9999999392252902907785028219223e-09));
    float _1493 = _1484 * float(frame.punctualLights[1].positionFalloff.w);
    float _1498 = fast::clamp(fma(-_1493, _1493, 1.0), 0.0, 1.0);
    float _1517 = fast::clamp(fma(dot(-_1489, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1632 = fast::normalize(_780 + _1489);
    float _1577 = fast::clamp(dot(_774, _1489), 0.0, 1.0);
    float4 _1694 = float4(cross(_774, _1632), params.facet_alpha * fast::clamp(dot(_774, _1632), 0.0, 1.0)) * 64.0;
    float _1676 = _1345 / dot(_1694, _1694);
    float _1738 = 1.0 - fast::clamp(dot(_1489, _1632), 0.0, 1.0);
    float _1741 = _1738 * _1738;
    float3 _1771 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_780, _774), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1086.xxx, _1086.yyy, float3(params.facet_f0)) * _1105, fast::min((((float3(params.facet_f0) + (_1424 * ((_1416 * _1416) * _1413))) * (((_1351 * _1351) * 0.3183098733425140380859375) * (0.5 / fma(_1252, _1390, _1047 * sqrt(fma(_1252 * _1252, _1386, _1380)))))) * _1105) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1173 * _1173) / fast::max(_1159, 9.9999997473787516355514526367188e-05)) * _1192) * _1192)) * _1252), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1424 * ((_1741 * _1741) * _1738))) * (((_1676 * _1676) * 0.3183098733425140380859375) * (0.5 / fma(_1577, _1390, _1047 * sqrt(fma(_1577 * _1577, _1386, _1380)))))) * _1105) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1498 * _1498) / fast::max(_1484, 9.9999997473787516355514526367188e-05)) * _1517) * _1517)) * _1577), float3(65504.0));
    out.fragColor = float4(_1771, 1.0);
    return out;
}

