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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    float3 _945 = fast::normalize(in.v_normal);
    float3 _951 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1233 = fast::max(dot(_945, _951), 9.9999997473787516355514526367188e-05);
    float3 _1237 = reflect(-_951, _945);
    float4 _1275 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1233, params.facet_perceptualRoughness), level(0.0));
    float3 _1294 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1275.y) - 1.0));
    float _1340 = 1.0 - _1233;
    float _1343 = _1340 * _1340;
    float _1350 = fma(0.959999978542327880859375, (_1343 * _1343) * _1340, 0.039999999105930328369140625);
    float _1320 = fma(-_1350, params.facet_clearCoat, 1.0);
    float3 _1389 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1392 = dot(_1389, _1389);
    float3 _1397 = _1389 * rsqrt(fast::max(_1392, 9.9999999392252902907785028219223e-09));
    float _1401 = _1392 * float(frame.punctualLights[0].positionFalloff.w);
    float _1406 = fast::clamp(fma(-_1401, _1401, 1.0), 0.0, 1.0);
    float _1425 = fast::clamp(fma(dot(-_1397, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1487 = fast::clamp(dot(_945, _1397), 0.0, 1.0);
    float3 _1557 = fast::normalize(_951 + _1397);
    float _1494 = fast::clamp(dot(_945, _1557), 0.0, 1.0);
    float _1498 = fast::clamp(dot(_1397, _1557), 0.0, 1.0);
    float _1595 = 4096.0 * params.facet_alpha;
    float3 _1613 = cross(_945, _1557) * 64.0;
    float _1615 = 64.0 * params.facet_alpha;
    float _1617 = _1615 * _1494;
    float _1620 = dot(_1613, _1613);
    float _1601 = _1595 / fma(_1617, _1617, _1620);
    float _1632 = params.facet_alpha * params.facet_alpha;
    float _1638 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1642 = sqrt(fma(_1233 * _1233, _1638, _1632));
    float _1665 = 1.0 - _1498;
    float _1668 = _1665 * _1665;
    float _1673 = (_1668 * _1668) * _1665;
    float3 _1676 = float3(1.0) - float3(params.facet_f0);
    float _1759 = 64.0 * params.facet_clearCoatAlpha;
    float _1761 = _1759 * _1494;
    float _1714 = 12.56637096405029296875 * fast::max(_1498 * _1498, 6.103515625e-05);
    float _1716 = 4096.0 * params.facet_clearCoatAlpha;
    float _1720 = _1716 / (fma(_1761, _1761, _1620) * _1714);
    float _1737 = 0.959999978542327880859375 * params.facet_clearCoat;
    float3 _1826 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1829 = dot(_1826, _1826);
    float3 _1834 = _1826 * rsqrt(fast::max(_1829, 9.9999999392252902907785028219223e-09));
    float _1838 = _1829 * float(frame.punctualLights[1].positionFalloff.w);
    float _1843 = fast::clamp(fma(-_1838, _1838, 1.0), 0.0, 1.0);
    float _1862 = fast::clamp(fma(dot(-_1834, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1924 = fast::clamp(dot(_945, _1834), 0.0, 1.0);
    float3 _1994 = fast::normalize(_951 + _1834);
    float _1931 = fast::clamp(dot(_945, _1994), 0.0, 1.0);
    float _1935 = fast::clamp(dot(_1834, _1994), 0.0, 1.0);
    float3 _2050 = cross(_945, _1994) * 64.0;
    float _2054 = _1615 * _1931;
    float _2057 = dot(_2050, _2050);
    float _2038 = _1595 / fma(_2054, _2054, _2057);
    float _2102 = 1.0 - _1935;
    float _2105 = _2102 * _2102;
    float _2110 = (_2105 * _2105) * _2102;
    float _2198 = _1759 * _1931;
    float _2151 = 12.56637096405029296875 * fast::max(_1935 * _1935, 6.103515625e-05);
    float _2157 = _1716 / (fma(_2198, _2198, _2057) * _2151);
    float3 _2228 = (mix(facet_environment.sample(facet_environmentSmplr, _1237, level(params.facet_environmentLod)).xyz * (mix(_1275.xxx, _1275.yyy, float3(params.facet_f0)) * _1294), facet_environment.sample(facet_environmentSmplr, _1237, level(params.facet_clearCoatLod)).xyz, float3(_1350 * params.facet_clearCoat)) + fast::min(fast::min(((((float3(params.facet_f0) + (_1676 * _1673)) * (((_1601 * _1601) * 0.3183098733425140380859375) * (0.5 / fma(_1487, _1642, _1233 * sqrt(fma(_1487 * _1487, _1638, _1632)))))) * _1294) * _1320) + float3((_1720 * (_1720 * _1714)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1737 * _1673)), float3(65504.0)) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1406 * _1406) / fast::max(_1392, 9.9999997473787516355514526367188e-05)) * _1425) * _1425)) * _1487), float3(65504.0))) + fast::min(fast::min(((((float3(params.facet_f0) + (_1676 * _2110)) * (((_2038 * _2038) * 0.3183098733425140380859375) * (0.5 / fma(_1924, _1642, _1233 * sqrt(fma(_1924 * _1924, _1638, _1632)))))) * _1294) * _1320) + float3((_2157 * (_2157 * _2151)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1737 * _2110)), float3(65504.0)) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1843 * _1843) / fast::max(_1829, 9.9999997473787516355514526367188e-05)) * _1862) * _1862)) * _1924), float3(65504.0));
    out.fragColor = float4(_2228, 1.0);
    return out;
}

