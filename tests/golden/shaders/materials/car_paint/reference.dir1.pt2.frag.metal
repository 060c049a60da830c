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
    float3 _966 = fast::normalize(in.v_normal);
    float3 _972 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1276 = fast::max(dot(_966, _972), 9.9999997473787516355514526367188e-05);
    float3 _1280 = reflect(-_972, _966);
    float4 _1315 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1276, params.facet_perceptualRoughness), level(0.0));
    float3 _1334 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1315.y) - 1.0));
    float _1392 = 1.0 - _1276;
    float _1395 = _1392 * _1392;
    float _1402 = fma(0.959999978542327880859375, (_1395 * _1395) * _1392, 0.039999999105930328369140625);
    float _1407 = fast::clamp(params.coat, 0.0, 1.0);
    float _1374 = fma(-_1402, _1407, 1.0);
    float _1412 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1546 = fast::normalize(_972 + frame.lightDirection.xyz);
    float _1479 = fast::clamp(dot(_966, frame.lightDirection.xyz), 0.0, 1.0);
    float _1483 = fast::clamp(dot(_966, _1546), 0.0, 1.0);
    float _1487 = fast::clamp(dot(frame.lightDirection.xyz, _1546), 0.0, 1.0);
    float _1584 = 4096.0 * params.facet_alpha;
    float3 _1602 = cross(_966, _1546) * 64.0;
    float _1604 = 64.0 * params.facet_alpha;
    float _1606 = _1604 * _1483;
    float _1609 = dot(_1602, _1602);
    float _1590 = _1584 / fma(_1606, _1606, _1609);
    float _1621 = params.facet_alpha * params.facet_alpha;
    float _1627 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1631 = sqrt(fma(_1276 * _1276, _1627, _1621));
    float _1654 = 1.0 - _1487;
    float _1657 = _1654 * _1654;
    float _1662 = (_1657 * _1657) * _1654;
    float3 _1665 = float3(1.0) - float3(params.facet_f0);
    float _1697 = _1412 * _1412;
    float _1753 = 64.0 * _1697;
    float _1755 = _1753 * _1483;
    float _1707 = 12.56637096405029296875 * fast::max(_1487 * _1487, 6.103515625e-05);
    float _1709 = 4096.0 * _1697;
    float _1713 = _1709 / (fma(_1755, _1755, _1609) * _1707);
    float _1730 = 0.959999978542327880859375 * _1407;
    float3 _1821 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1824 = dot(_1821, _1821);
    float3 _1829 = _1821 * rsqrt(fast::max(_1824, 9.9999999392252902907785028219223e-09));
    float _1833 = _1824 * float(frame.punctualLights[0].positionFalloff.w);
    float _1838 = fast::clamp(fma(-_1833, _1833, 1.0), 0.0, 1.0);
    float _1857 = fast::clamp(fma(dot(-_1829, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1989 = fast::normalize(_972 + _1829);
    float _1922 = fast::clamp(dot(_966, _1829), 0.0, 1.0);
    float _1926 = fast::clamp(dot(_966, _1989), 0.0, 1.0);
    float _1930 = fast::clamp(dot(_1829, _1989), 0.0, 1.0);
    float3 _2045 = cross(_966, _1989) * 64.0;
    float _2049 = _1604 * _1926;
    float _2052 = dot(_2045, _2045);
    float _2033 = _1584 / fma(_2049, _2049, _2052);
    float _2097 = 1.0 - _1930;
    float _2100 = _2097 * _2097;
    float _2105 = (_2100 * _2100) * _2097;
    float _2198 = _1753 * _1926;
    float _2150 = 12.56637096405029296875 * fast::max(_1930 * _1930, 6.103515625e-05);
    float _2156 = _1709 / (fma(_2198, _2198, _2052) * _2150);
    float3 _2229 = (mix(facet_environment.sample(facet_environmentSmplr, _1280, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1315.xxx, _1315.yyy, float3(params.facet_f0)) * _1334), facet_environment.sample(facet_environmentSmplr, _1280, level(_1412 * (4.0 * (2.0 - _1412)))).xyz, float3(_1402 * _1407)) + fast::min(fast::min(((((float3(params.facet_f0) + (_1665 * _1662)) * (((_1590 * _1590) * 0.3183098733425140380859375) * (0.5 / fma(_1479, _1631, _1276 * sqrt(fma(_1479 * _1479, _1627, _1621)))))) * _1334) * _1374) + float3((_1713 * (_1713 * _1707)) * fma(0.039999999105930328369140625, _1407, _1730 * _1662)), float3(65504.0)) * (frame.lightColor.xyz * _1479), float3(65504.0))) + fast::min(fast::min(((((float3(params.facet_f0) + (_1665 * _2105)) * (((_2033 * _2033) * 0.3183098733425140380859375) * (0.5 / fma(_1922, _1631, _1276 * sqrt(fma(_1922 * _1922, _1627, _1621)))))) * _1334) * _1374) + float3((_2156 * (_2156 * _2150)) * fma(0.039999999105930328369140625, _1407, _1730 * _2105)), float3(65504.0)) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1838 * _1838) / fast::max(_1824, 9.9999997473787516355514526367188e-05)) * _1857) * _1857)) * _1922), float3(65504.0));
    float3 _2264 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2267 = dot(_2264, _2264);
    float3 _2272 = _2264 * rsqrt(fast::max(_2267, 9.9999999392252902907785028219223e-09));
    float _2276 = _2267 * float(frame.punctualLights[1].positionFalloff.w);
    float _2281 = fast::clamp(fma(-_2276, _2276, 1.0), 0.0, 1.0);
    float _2300 = fast::clamp(fma(dot(-_2272, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2432 = fast::normalize(_972 + _2272);
    float _2365 = fast::clamp(dot(_966, _2272), 0.0, 1.0);
    float _2369 = fast::clamp(dot(_966, _2432), 0.0, 1.0);
    float _2373 = fast::clamp(dot(_2272, _2432), 0.0, 1.0);
    float3 _2488 = cross(_966, _2432) * 64.0;
    float _2492 = _1604 * _2369;
    float _2495 = dot(_2488, _2488);
    float _2476 = _1584 / fma(_2492, _2492, _2495);
    float _2540 = 1.0 - _2373;
    float _2543 = _2540 * _2540;
    float _2548 = (_2543 * _2543) * _2540;
    float _2641 = _1753 * _2369;
    float _2593 = 12.56637096405029296875 * fast::max(_2373 * _2373, 6.103515625e-05);
    float _2599 = _1709 / (fma(_2641, _2641, _2495) * _2593);
    out.fragColor = float4(_2229 + fast::min(fast::min(((((float3(params.facet_f0) + (_1665 * _2548)) * (((_2476 * _2476) * 0.3183098733425140380859375) * (0.5 / fma(_2365, _1631, _1276 * sqrt(fma(_2365 * _2365, _1627, _1621)))))) * _1334) * _1374) + float3((_2599 * (_2599 * _2593)) * fma(0.039999999105930328369140625, _1407, _1730 * _2548)), float3(65504.0)) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2281 * _2281) / fast::max(_2267, 9.9999997473787516355514526367188e-05)) * _2300) * _2300)) * _2365), float3(65504.0)), 1.0);
    return out;
}

