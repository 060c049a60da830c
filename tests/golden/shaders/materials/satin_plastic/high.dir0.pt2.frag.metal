#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _963 = normalize(half3(in.v_normal));
    float3 _969 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1115 = _963.y;
    half _1120 = _963.z;
    half _1125 = _963.x;
    half3 _1193 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1115)) + (half4(frame.sh[2]).xyz * _1120)) + (half4(frame.sh[3]).xyz * _1125)) + (((((half4(frame.sh[4]).xyz * (_1125 * _1115)) + (half4(frame.sh[5]).xyz * (_1115 * _1120))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1120, _1120, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1125 * _1120))) + (half4(frame.sh[8]).xyz * fma(_1125, _1125, half(-float(_1115 * _1115))))), half3(float3(0.0)));
    half _1243 = max(dot(_963, half3(_969)), half(9.9999997473787516355514526367188e-05));
    half3 _1247 = reflect(-half3(_969), _963);
    float4 _1282 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1243, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1301 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1282).y) - half(1.0)));
    float4 _1308 = facet_environment.sample(facet_environmentSmplr, float3(_1247), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1385 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1342 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1243, _1385)), level(0.0));
    half3 _1392 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2394 = half4(_1342);
    half _1355 = _2394.z;
    half _1357 = fma(half(-float(max(_1392.x, max(_1392.y, _1392.z)))), _1355, half(1.0));
    half _1401 = _1385 * _1385;
    half4 _2398 = half4(_1342);
    half _1362 = _2398.w;
    float4 _1413 = facet_environment.sample(facet_environmentSmplr, float3(_1247), level(_1385 * half(4.0)));
    float3 _1450 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1453 = dot(_1450, _1450);
    float3 _1458 = _1450 * rsqrt(fast::max(_1453, 9.9999999392252902907785028219223e-09));
    float _1462 = _1453 * float(frame.punctualLights[0].positionFalloff.w);
    float _1467 = fast::clamp(fma(-_1462, _1462, 1.0), 0.0, 1.0);
    float _1486 = fast::clamp(fma(dot(-_1458, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1497 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1467) * half(_1467)) / fast::max(_1453, 9.9999997473787516355514526367188e-05)) * half(_1486)) * half(_1486)), float3(65504.0));
    float3 _1622 = fast::normalize(_969 + _1458);
    half _1554 = clamp(dot(_963, half3(_1458)), half(0.0), half(1.0));
    half _1558 = clamp(dot(_963, half3(_1622)), half(0.0), half(1.0));
    half3 _1662 = cross(_963, half3(_1622));
    half _1665 = _1558 * half(params.facet_alpha);
    half _1674 = half(params.facet_alpha) / fma(_1665, _1665, dot(_1662, _1662));
    half _1688 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1694 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1698 = sqrt(fma(_1243 * _1243, _1694, _1688));
    half _1722 = half(1.0) - clamp(dot(half3(_1458), half3(_1622)), half(0.0), half(1.0));
    half _1725 = _1722 * _1722;
    half3 _1733 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1766 = half(8192.0) * fma(half(-float(_1554)), _1243, _1554 + _1243);
    half _1770 = half(1.0) / (_1401 * _1766);
    half _1777 = half(2048.0) * _1401;
    half3 _1595 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1603 = min(fma(fma((half3(float3(params.facet_f0)) + (_1733 * ((_1725 * _1725) * _1722))) * min(min((_1674 * _1674) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1554, _1698, _1243 * sqrt(fma(_1554 * _1554, _1694, _1688))), half(65504.0)), half(65504.0)), _1301, _1595), (half3(_1497) * _1554) * _1357, (_1392 * ((((fma(_1770, _1766, half(2.0)) * pow(max(fma(half(-float(_1558)), _1558, half(1.0)), half(0.0)), half(0.5) * (_1770 * _1766))) * half(0.15915493667125701904296875)) * (_1554 * (_1770 * _1777))) * _1362)) * half3(_1497)), half3(float3(65504.0)));
    float3 _1841 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1844 = dot(_1841, _1841);
    float3 _1849 = _1841 * rsqrt(fast::max(_1844, 9.9999999392252902907785028219223e-09));
    float _1853 = _1844 * float(frame.punctualLights[1].positionFalloff.w);
    float _1858 = fast::clamp(fma(-_1853, _1853, 1.0), 0.0, 1.0);
    float _1877 = fast::clamp(fma(dot(-_1849, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1888 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1858) * half(_1858)) / fast::max(_1844, 9.9999997473787516355514526367188e-05)) * half(_1877)) * half(_1877)), float3(65504.0));
    float3 _2013 = fast::normalize(_969 + _1849);
    half _1945 = clamp(dot(_963, half3(_1849)), half(0.0), half(1.0));
    half _1949 = clamp(dot(_963, half3(_2013)), half(0.0), half(1.0));
    half3 _2053 = cross(_963, half3(_2013));
    half _2056 = _1949 * half(params.facet_alpha);
    half _2065 = half(params.facet_alpha) / fma(_2056, _2056, dot(_2053, _2053));
    half _2113 = half(1.0) - clamp(dot(half3(_1849), half3(_2013)), half(0.0), half(1.0));
    half _2116 = _2113 * _2113;
    half _2157 = half(8192.0) * fma(half(-float(_1945)), _1243, _1945 + _1243);
    half _2161 = half(1.0) / (_1401 * _2157);
    half3 _1994 = min(fma(fma((half3(float3(params.facet_f0)) + (_1733 * ((_2116 * _2116) * _2113))) * min(min((_2065 * _2065) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1945, _1698, _1243 * sqrt(fma(_1945 * _1945, _1694, _1688))), half(65504.0)), half(65504.0)), _1301, _1595), (half3(_1888) * _1945) * _1357, (_1392 * ((((fma(_2161, _2157, half(2.0)) * pow(max(fma(half(-float(_1949)), _1949, half(1.0)), half(0.0)), half(0.5) * (_2161 * _2157))) * half(0.15915493667125701904296875)) * (_1945 * (_2161 * _1777))) * _1362)) * half3(_1888)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1413).xyz, _1392 * _1355, fma(half3(float3(params.facet_diffuseColor)), _1193, half4(_1308).xyz * (mix(half4(_1282).xxx, half4(_1282).yyy, half3(float3(params.facet_f0))) * _1301)) * _1357) + _1603) + _1994, half(1.0)));
    return out;
}

