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
    float3 _954 = fast::normalize(in.v_normal);
    float3 _960 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1264 = fast::max(dot(_954, _960), 9.9999997473787516355514526367188e-05);
    float3 _1268 = reflect(-_960, _954);
    float4 _1303 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1264, params.facet_perceptualRoughness), level(0.0));
    float3 _1322 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1303.y) - 1.0));
    float _1382 = 1.0 - _1264;
    float _1385 = _1382 * _1382;
    float _1392 = fma(0.959999978542327880859375, (_1385 * _1385) * _1382, 0.039999999105930328369140625);
    float _1397 = fast::clamp(params.coat, 0.0, 1.0);
    float _1364 = fma(-_1392, _1397, 1.0);
    float _1402 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1538 = fast::normalize(_960 + frame.lightDirection.xyz);
    float _1472 = fast::clamp(dot(_954, frame.lightDirection.xyz), 0.0, 1.0);
    float _1476 = fast::clamp(dot(_954, _1538), 0.0, 1.0);
    float _1480 = fast::clamp(dot(frame.lightDirection.xyz, _1538), 0.0, 1.0);
    float3 _1576 = cross(_954, _1538);
    float _1579 = _1476 * params.facet_alpha;
    float _1583 = dot(_1576, _1576);
    float _1588 = params.facet_alpha / fma(_1579, _1579, _1583);
    float _1601 = params.facet_alpha * params.facet_alpha;
    float _1607 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1611 = sqrt(fma(_1264 * _1264, _1607, _1601));
    float _1634 = 1.0 - _1480;
    float _1637 = _1634 * _1634;
    float _1642 = (_1637 * _1637) * _1634;
    float3 _1645 = float3(1.0) - float3(params.facet_f0);
    float3 _1498 = frame.lightColor.xyz * _1472;
    float _1679 = _1402 * _1402;
    float _1685 = _1476 * _1679;
    float _1696 = fast::max(_1480 * _1480, 6.103515625e-05);
    float _1699 = 2048.0 * _1679;
    float _1704 = _1699 / (fma(_1685, _1685, _1583) * (_1696 * 25735.927734375));
    float3 _1801 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1804 = dot(_1801, _1801);
    float3 _1809 = _1801 * rsqrt(fast::max(_1804, 9.9999999392252902907785028219223e-09));
    float _1813 = _1804 * float(frame.punctualLights[0].positionFalloff.w);
    float _1818 = fast::clamp(fma(-_1813, _1813, 1.0), 0.0, 1.0);
    float _1837 = fast::clamp(fma(dot(-_1809, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1969 = fast::normalize(_960 + _1809);
    float _1903 = fast::clamp(dot(_954, _1809), 0.0, 1.0);
    float _1907 = fast::clamp(dot(_954, _1969), 0.0, 1.0);
    float _1911 = fast::clamp(dot(_1809, _1969), 0.0, 1.0);
    float3 _2007 = cross(_954, _1969);
    float _2010 = _1907 * params.facet_alpha;
    float _2014 = dot(_2007, _2007);
    float _2019 = params.facet_alpha / fma(_2010, _2010, _2014);
    float _2065 = 1.0 - _1911;
    float _2068 = _2065 * _2065;
    float _2073 = (_2068 * _2068) * _2065;
    float3 _1929 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1818 * _1818) / fast::max(_1804, 9.9999997473787516355514526367188e-05)) * _1837) * _1837)) * _1903;
    float _2116 = _1907 * _1679;
    float _2127 = fast::max(_1911 * _1911, 6.103515625e-05);
    float _2135 = _1699 / (fma(_2116, _2116, _2014) * (_2127 * 25735.927734375));
    float3 _2232 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2235 = dot(_2232, _2232);
    float3 _2240 = _2232 * rsqrt(fast::max(_2235, 9.9999999392252902907785028219223e-09));
    float _2244 = _2235 * float(frame.punctualLights[1].positionFalloff.w);
    float _2249 = fast::clamp(fma(-_2244, _2244, 1.0), 0.0, 1.0);
    float _2268 = fast::clamp(fma(dot(-_2240, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2400 = fast::normalize(_960 + _2240);
    float _2334 = fast::clamp(dot(_954, _2240), 0.0, 1.0);
    float _2338 = fast::clamp(dot(_954, _2400), 0.0, 1.0);
    float _2342 = fast::clamp(dot(_2240, _2400), 0.0, 1.0);
    float3 _2438 = cross(_954, _2400);
    float _2441 = _2338 * params.facet_alpha;
    float _2445 = dot(_2438, _2438);
    float _2450 = params.facet_alpha / fma(_2441, _2441, _2445);
    float _2496 = 1.0 - _2342;
    float _2499 = _2496 * _2496;
    float _2504 = (_2499 * _2499) * _2496;
    float3 _2360 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2249 * _2249) / fast::max(_2235, 9.9999997473787516355514526367188e-05)) * _2268) * _2268)) * _2334;
    float _2547 = _2338 * _1679;
    float _2558 = fast::max(_2342 * _2342, 6.103515625e-05);
    float _2566 = _1699 / (fma(_2547, _2547, _2445) * (_2558 * 25735.927734375));
    float3 _2628 = ((mix(facet_environment.sample(facet_environmentSmplr, _1268, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1303.xxx, _1303.yyy, float3(params.facet_f0)) * _1322), facet_environment.sample(facet_environmentSmplr, _1268, level(_1402 * (4.0 * (2.0 - _1402)))).xyz, float3(_1392 * _1397)) + fast::min(fma(((float3(params.facet_f0) + (_1645 * _1642)) * (((_1588 * _1588) * 0.3183098733425140380859375) * (0.5 / fma(_1472, _1611, _1264 * sqrt(fma(_1472 * _1472, _1607, _1601)))))) * _1322, _1498 * _1364, _1498 * ((_1704 * (_1704 * (12.56637096405029296875 * _1696))) * (fma(0.959999978542327880859375, _1642, 0.039999999105930328369140625) * _1397))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1645 * _2073)) * (((_2019 * _2019) * 0.3183098733425140380859375) * (0.5 / fma(_1903, _1611, _1264 * sqrt(fma(_1903 * _1903, _1607, _1601)))))) * _1322, _1929 * _1364, _1929 * ((_2135 * (_2135 * (12.56637096405029296875 * _2127))) * (fma(0.959999978542327880859375, _2073, 0.039999999105930328369140625) * _1397))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1645 * _2504)) * (((_2450 * _2450) * 0.3183098733425140380859375) * (0.5 / fma(_2334, _1611, _1264 * sqrt(fma(_2334 * _2334, _1607, _1601)))))) * _1322, _2360 * _1364, _2360 * ((_2566 * (_2566 * (12.56637096405029296875 * _2558))) * (fma(0.959999978542327880859375, _2504, 0.039999999105930328369140625) * _1397))), float3(65504.0));
    out.fragColor = float4(_2628, 1.0);
    return out;
}

