#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    float3 _933 = fast::normalize(in.v_normal);
    float3 _939 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1225 = fast::max(dot(_933, _939), 9.9999997473787516355514526367188e-05);
    float3 _1229 = reflect(-_939, _933);
    float4 _1264 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1225, params.facet_perceptualRoughness), level(0.0));
    float3 _1283 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1264.y) - 1.0));
    float _1338 = 1.0 - _1225;
    float _1341 = _1338 * _1338;
    float _1348 = fma(0.959999978542327880859375, (_1341 * _1341) * _1338, 0.039999999105930328369140625);
    float _1353 = fast::clamp(params.coat, 0.0, 1.0);
    float _1320 = fma(-_1348, _1353, 1.0);
    float _1358 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1401 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1404 = dot(_1401, _1401);
    float3 _1409 = _1401 * rsqrt(fast::max(_1404, 9.9999999392252902907785028219223e-09));
    float _1413 = _1404 * float(frame.punctualLights[0].positionFalloff.w);
    float _1418 = fast::clamp(fma(-_1413, _1413, 1.0), 0.0, 1.0);
    float _1437 = fast::clamp(fma(dot(-_1409, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1569 = fast::normalize(_939 + _1409);
    float _1503 = fast::clamp(dot(_933, _1409), 0.0, 1.0);
    float _1507 = fast::clamp(dot(_933, _1569), 0.0, 1.0);
    float _1511 = fast::clamp(dot(_1409, _1569), 0.0, 1.0);
    float3 _1607 = cross(_933, _1569);
    float _1610 = _1507 * params.facet_alpha;
    float _1614 = dot(_1607, _1607);
    float _1619 = params.facet_alpha / fma(_1610, _1610, _1614);
    float _1632 = params.facet_alpha * params.facet_alpha;
    float _1638 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1642 = sqrt(fma(_1225 * _1225, _1638, _1632));
    float _1665 = 1.0 - _1511;
    float _1668 = _1665 * _1665;
    float _1673 = (_1668 * _1668) * _1665;
    float3 _1676 = float3(1.0) - float3(params.facet_f0);
    float3 _1529 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1418 * _1418) / fast::max(_1404, 9.9999997473787516355514526367188e-05)) * _1437) * _1437)) * _1503;
    float _1714 = _1358 * _1358;
    float _1766 = _1507 * _1714;
    float _1775 = _1714 / fma(_1766, _1766, _1614);
    float3 _1841 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1844 = dot(_1841, _1841);
    float3 _1849 = _1841 * rsqrt(fast::max(_1844, 9.9999999392252902907785028219223e-09));
    float _1853 = _1844 * float(frame.punctualLights[1].positionFalloff.w);
    float _1858 = fast::clamp(fma(-_1853, _1853, 1.0), 0.0, 1.0);
    float _1877 = fast::clamp(fma(dot(-_1849, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2009 = fast::normalize(_939 + _1849);
    float _1943 = fast::clamp(dot(_933, _1849), 0.0, 1.0);
    float _1947 = fast::clamp(dot(_933, _2009), 0.0, 1.0);
    float _1951 = fast::clamp(dot(_1849, _2009), 0.0, 1.0);
    float3 _2047 = cross(_933, _2009);
    float _2050 = _1947 * params.facet_alpha;
    float _2054 = dot(_2047, _2047);
    float _2059 = params.facet_alpha / fma(_2050, _2050, _2054);
    float _2105 = 1.0 - _1951;
    float _2108 = _2105 * _2105;
    float _2113 = (_2108 * _2108) * _2105;
    float3 _1969 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1858 * _1858) / fast::max(_1844, 9.9999997473787516355514526367188e-05)) * _1877) * _1877)) * _1943;
    float _2206 = _1947 * _1714;
    float _2215 = _1714 / fma(_2206, _2206, _2054);
    float3 _2246 = (mix(facet_environment.sample(facet_environmentSmplr, _1229, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1264.xxx, _1264.yyy, float3(params.facet_f0)) * _1283), facet_environment.sample(facet_environmentSmplr, _1229, level(_1358 * 4.0)).xyz, float3(_1348 * _1353)) + fast::min(fma(((float3(params.facet_f0) + (_1676 * _1673)) * (((_1619 * _1619) * 0.3183098733425140380859375) * (0.5 / fma(_1503, _1642, _1225 * sqrt(fma(_1503 * _1503, _1638, _1632)))))) * _1283, _1529 * _1320, _1529 * ((((_1775 * _1775) * 0.3183098733425140380859375) * (0.25 / fast::max(_1511 * _1511, 6.103515625e-05))) * (fma(0.959999978542327880859375, _1673, 0.039999999105930328369140625) * _1353))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1676 * _2113)) * (((_2059 * _2059) * 0.3183098733425140380859375) * (0.5 / fma(_1943, _1642, _1225 * sqrt(fma(_1943 * _1943, _1638, _1632)))))) * _1283, _1969 * _1320, _1969 * ((((_2215 * _2215) * 0.3183098733425140380859375) * (0.25 / fast::max(_1951 * _1951, 6.103515625e-05))) * (fma(0.959999978542327880859375, _2113, 0.039999999105930328369140625) * _1353))), float3(65504.0));
    out.fragColor = float4(_2246, 1.0);
    return out;
}

