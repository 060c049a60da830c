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
    float3 _969 = fast::normalize(in.v_normal);
    float3 _975 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1279 = fast::max(dot(_969, _975), 9.9999997473787516355514526367188e-05);
    float3 _1283 = reflect(-_975, _969);
    float4 _1318 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1279, params.facet_perceptualRoughness), level(0.0));
    float3 _1337 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1318.y) - 1.0));
    float _1394 = fast::clamp(params.coat, 0.0, 1.0);
    float _1400 = 1.0 - _1279;
    float _1403 = _1400 * _1400;
    float _1407 = 0.959999978542327880859375 * _1394;
    float _1414 = fma(0.039999999105930328369140625, _1394, _1407 * ((_1403 * _1403) * _1400));
    float _1377 = 1.0 - _1414;
    float _1419 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1553 = fast::normalize(_975 + frame.lightDirection.xyz);
    float _1487 = fast::clamp(dot(_969, frame.lightDirection.xyz), 0.0, 1.0);
    float _1491 = fast::clamp(dot(_969, _1553), 0.0, 1.0);
    float _1495 = fast::clamp(dot(frame.lightDirection.xyz, _1553), 0.0, 1.0);
    float _1591 = 4096.0 * params.facet_alpha;
    float3 _1609 = cross(_969, _1553) * 64.0;
    float _1611 = 64.0 * params.facet_alpha;
    float _1613 = _1611 * _1491;
    float _1616 = dot(_1609, _1609);
    float _1597 = _1591 / fma(_1613, _1613, _1616);
    float _1628 = params.facet_alpha * params.facet_alpha;
    float _1634 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1638 = sqrt(fma(_1279 * _1279, _1634, _1628));
    float _1661 = 1.0 - _1495;
    float _1664 = _1661 * _1661;
    float _1669 = (_1664 * _1664) * _1661;
    float3 _1672 = float3(1.0) - float3(params.facet_f0);
    float3 _1513 = frame.lightColor.xyz * _1487;
    float _1709 = _1419 * _1419;
    float _1756 = 64.0 * _1709;
    float _1758 = _1756 * _1491;
    float _1719 = 12.56637096405029296875 * fast::max(_1495 * _1495, 6.103515625e-05);
    float _1721 = 4096.0 * _1709;
    float _1725 = _1721 / (fma(_1758, _1758, _1616) * _1719);
    float3 _1844 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1847 = dot(_1844, _1844);
    float3 _1852 = _1844 * rsqrt(fast::max(_1847, 9.9999999392252902907785028219223e-09));
    float _1856 = _1847 * float(frame.punctualLights[0].positionFalloff.w);
    float _1861 = fast::clamp(fma(-_1856, _1856, 1.0), 0.0, 1.0);
    float _1880 = fast::clamp(fma(dot(-_1852, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2012 = fast::normalize(_975 + _1852);
    float _1946 = fast::clamp(dot(_969, _1852), 0.0, 1.0);
    float _1950 = fast::clamp(dot(_969, _2012), 0.0, 1.0);
    float _1954 = fast::clamp(dot(_1852, _2012), 0.0, 1.0);
    float3 _2068 = cross(_969, _2012) * 64.0;
    float _2072 = _1611 * _1950;
    float _2075 = dot(_2068, _2068);
    float _2056 = _1591 / fma(_2072, _2072, _2075);
    float _2120 = 1.0 - _1954;
    float _2123 = _2120 * _2120;
    float _2128 = (_2123 * _2123) * _2120;
    float3 _1972 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1861 * _1861) / fast::max(_1847, 9.9999997473787516355514526367188e-05)) * _1880) * _1880)) * _1946;
    float _2217 = _1756 * _1950;
    float _2178 = 12.56637096405029296875 * fast::max(_1954 * _1954, 6.103515625e-05);
    float _2184 = _1721 / (fma(_2217, _2217, _2075) * _2178);
    float3 _2303 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2306 = dot(_2303, _2303);
    float3 _2311 = _2303 * rsqrt(fast::max(_2306, 9.9999999392252902907785028219223e-09));
    float _2315 = _2306 * float(frame.punctualLights[1].positionFalloff.w);
    float _2320 = fast::clamp(fma(-_2315, _2315, 1.0), 0.0, 1.0);
    float _2339 = fast::clamp(fma(dot(-_2311, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2471 = fast::normalize(_975 + _2311);
    float _2405 = fast::clamp(dot(_969, _2311), 0.0, 1.0);
    float _2409 = fast::clamp(dot(_969, _2471), 0.0, 1.0);
    float _2413 = fast::clamp(dot(_2311, _2471), 0.0, 1.0);
    float3 _2527 = cross(_969, _2471) * 64.0;
    float _2531 = _1611 * _2409;
    float _2534 = dot(_2527, _2527);
    float _2515 = _1591 / fma(_2531, _2531, _2534);
    float _2579 = 1.0 - _2413;
    float _2582 = _2579 * _2579;
    float _2587 = (_2582 * _2582) * _2579;
    float3 _2431 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2320 * _2320) / fast::max(_2306, 9.9999997473787516355514526367188e-05)) * _2339) * _2339)) * _2405;
    float _2676 = _1756 * _2409;
    float _2637 = 12.56637096405029296875 * fast::max(_2413 * _2413, 6.103515625e-05);
    float _2643 = _1721 / (fma(_2676, _2676, _2534) * _2637);
    float3 _2727 = ((mix(facet_environment.sample(facet_environmentSmplr, _1283, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1318.xxx, _1318.yyy, float3(params.facet_f0)) * _1337), facet_environment.sample(facet_environmentSmplr, _1283, level(_1419 * (4.0 * (2.0 - _1419)))).xyz, float3(_1414)) + fast::min(fma(((float3(params.facet_f0) + (_1672 * _1669)) * (((_1597 * _1597) * 0.3183098733425140380859375) * (0.5 / fma(_1487, _1638, _1279 * sqrt(fma(_1487 * _1487, _1634, _1628)))))) * _1337, _1513 * _1377, _1513 * ((_1725 * (_1725 * _1719)) * fma(0.039999999105930328369140625, _1394, _1407 * _1669))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1672 * _2128)) * (((_2056 * _2056) * 0.3183098733425140380859375) * (0.5 / fma(_1946, _1638, _1279 * sqrt(fma(_1946 * _1946, _1634, _1628)))))) * _1337, _1972 * _1377, _1972 * ((_2184 * (_2184 * _2178)) * fma(0.039999999105930328369140625, _1394, _1407 * _2128))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1672 * _2587)) * (((_2515 * _2515) * 0.3183098733425140380859375) * (0.5 / fma(_2405, _1638, _1279 * sqrt(fma(_2405 * _2405, _1634, _1628)))))) * _1337, _2431 * _1377, _2431 * ((_2643 * (_2643 * _2637)) * fma(0.039999999105930328369140625, _1394, _1407 * _2587))), float3(65504.0));
    out.fragColor = float4(_2727, 1.0);
    return out;
}

