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
    float _1068 = fast::max(dot(_774, _780), 9.9999997473787516355514526367188e-05);
    float4 _1107 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1068, params.facet_perceptualRoughness), level(0.0));
    float3 _1126 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1107.y) - 1.0));
    float3 _1248 = fast::normalize(_780 + frame.lightDirection.xyz);
    float _1193 = fast::clamp(dot(_774, frame.lightDirection.xyz), 0.0, 1.0);
    float _1286 = 4096.0 * params.facet_alpha;
    float4 _1310 = float4(cross(_774, _1248), params.facet_alpha * fast::clamp(dot(_774, _1248), 0.0, 1.0)) * 64.0;
    float _1292 = _1286 / dot(_1310, _1310);
    float _1321 = params.facet_alpha * params.facet_alpha;
    float _1327 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1331 = sqrt(fma(_1068 * _1068, _1327, _1321));
    float _1354 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1248), 0.0, 1.0);
    float _1357 = _1354 * _1354;
    float3 _1365 = float3(1.0) - float3(params.facet_f0);
    float3 _1422 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1425 = dot(_1422, _1422);
    float3 _1430 = _1422 * rsqrt(fast::max(_1425, 9.9999999392252902907785028219223e-09));
    float _1434 = _1425 * float(frame.punctualLights[0].positionFalloff.w);
    float _1439 = fast::clamp(fma(-_1434, _1434, 1.0), 0.0, 1.0);
    float _1458 = fast::clamp(fma(dot(-_1430, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1573 = fast::normalize(_780 + _1430);
    float _1518 = fast::clamp(dot(_774, _1430), 0.0, 1.0);
    float4 _1635 = float4(cross(_774, _1573), params.facet_alpha * fast::clamp(dot(_774, _1573), 0.0, 1.0)) * 64.0;
    float _1617 = _1286 / dot(_1635, _1635);
    float _1679 = 1.0 - fast::clamp(dot(_1430, _1573), 0.0, 1.0);
    float _1682 = _1679 * _1679;
    float3 _1747 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1750 = dot(_1747, _1747);
    float3 _1755 = _1747 * rsqrt(fast::max(_1750, 9.9999999392252902907785028219223e-09));
    float _1759 = _1750 * float(frame.punctualLights[1].positionFalloff.w);
    float _1764 = fast::clamp(fma(-_1759, _1759, 1.0), 0.0, 1.0);
    float _1783 = fast::clamp(fma(dot(-_1755, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1898 = fast::normalize(_780 + _1755);
    float _1843 = fast::clamp(dot(_774, _1755), 0.0, 1.0);
    float4 _1960 = float4(cross(_774, _1898), params.facet_alpha * fast::clamp(dot(_774, _1898), 0.0, 1.0)) * 64.0;
    float _1942 = _1286 / dot(_1960, _1960);
    float _2004 = 1.0 - fast::clamp(dot(_1755, _1898), 0.0, 1.0);
    float _2007 = _2004 * _2004;
    float3 _2037 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_780, _774), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1107.xxx, _1107.yyy, float3(params.facet_f0)) * _1126, fast::min((((float3(params.facet_f0) + (_1365 * ((_1357 * _1357) * _1354))) * (((_1292 * _1292) * 0.3183098733425140380859375) * (0.5 / fma(_1193, _1331, _1068 * sqrt(fma(_1193 * _1193, _1327, _1321)))))) * _1126) * (frame.lightColor.xyz * _1193), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1365 * ((_1682 * _1682) * _1679))) * (((_1617 * _1617) * 0.3183098733425140380859375) * (0.5 / fma(_1518, _1331, _1068 * sqrt(fma(_1518 * _1518, _1327, _1321)))))) * _1126) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1439 * _1439) / fast::max(_1425, 9.9999997473787516355514526367188e-05)) * _1458) * _1458)) * _1518), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1365 * ((_2007 * _2007) * _2004))) * (((_1942 * _1942) * 0.3183098733425140380859375) * (0.5 / fma(_1843, _1331, _1068 * sqrt(fma(_1843 * _1843, _1327, _1321)))))) * _1126) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1764 * _1764) / fast::max(_1750, 9.9999997473787516355514526367188e-05)) * _1783) * _1783)) * _1843), float3(65504.0));
    out.fragColor = float4(_2037, 1.0);
    return out;
}

