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
    half3 _955 = normalize(half3(in.v_normal));
    float3 _961 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1243 = max(dot(_955, half3(_961)), half(9.9999997473787516355514526367188e-05));
    half3 _1247 = reflect(-half3(_961), _955);
    float4 _1285 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1243, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1304 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1285).y) - half(1.0)));
    float4 _1261 = facet_environment.sample(facet_environmentSmplr, float3(_1247), level(params.facet_environmentLod));
    half _1350 = half(1.0) - _1243;
    half _1353 = _1350 * _1350;
    half _1360 = fma(half(0.959999978542327880859375), (_1353 * _1353) * _1350, half(0.039999999105930328369140625));
    half _1330 = fma(half(-float(_1360)), half(params.facet_clearCoat), half(1.0));
    float4 _1338 = facet_environment.sample(facet_environmentSmplr, float3(_1247), level(params.facet_clearCoatLod));
    float3 _1400 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1403 = dot(_1400, _1400);
    float3 _1408 = _1400 * rsqrt(fast::max(_1403, 9.9999999392252902907785028219223e-09));
    float _1412 = _1403 * float(frame.punctualLights[0].positionFalloff.w);
    float _1417 = fast::clamp(fma(-_1412, _1412, 1.0), 0.0, 1.0);
    float _1436 = fast::clamp(fma(dot(-_1408, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1501 = clamp(dot(_955, half3(_1408)), half(0.0), half(1.0));
    float3 _1572 = fast::normalize(_961 + _1408);
    half _1508 = clamp(dot(_955, half3(_1572)), half(0.0), half(1.0));
    half _1512 = clamp(dot(half3(_1408), half3(_1572)), half(0.0), half(1.0));
    half _1612 = half(4096.0) * half(params.facet_alpha);
    half3 _1631 = cross(_955, half3(_1572)) * half(64.0);
    half _1633 = half(64.0) * half(params.facet_alpha);
    half _1635 = _1633 * _1508;
    half _1638 = dot(_1631, _1631);
    half _1618 = _1612 / fma(_1635, _1635, _1638);
    half _1650 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1656 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1660 = sqrt(fma(_1243 * _1243, _1656, _1650));
    half _1684 = half(1.0) - _1512;
    half _1687 = _1684 * _1684;
    half _1692 = (_1687 * _1687) * _1684;
    half3 _1695 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1779 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1781 = _1779 * _1508;
    half _1733 = half(12.56637096405029296875) * max(_1512 * _1512, half(6.103515625e-05));
    half _1735 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1739 = _1735 / (fma(_1781, _1781, _1638) * _1733);
    half _1757 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    half3 _1553 = min(min(((((half3(float3(params.facet_f0)) + (_1695 * _1692)) * min(min((_1618 * _1618) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1501, _1660, _1243 * sqrt(fma(_1501 * _1501, _1656, _1650))), half(65504.0)), half(65504.0))) * _1304) * _1330) + half3(min(_1739 * (_1739 * _1733), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1757 * _1692)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1417) * half(_1417)) / fast::max(_1403, 9.9999997473787516355514526367188e-05)) * half(_1436)) * half(_1436)), float3(65504.0))) * _1501), half3(float3(65504.0)));
    float3 _1847 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1850 = dot(_1847, _1847);
    float3 _1855 = _1847 * rsqrt(fast::max(_1850, 9.9999999392252902907785028219223e-09));
    float _1859 = _1850 * float(frame.punctualLights[1].positionFalloff.w);
    float _1864 = fast::clamp(fma(-_1859, _1859, 1.0), 0.0, 1.0);
    float _1883 = fast::clamp(fma(dot(-_1855, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1948 = clamp(dot(_955, half3(_1855)), half(0.0), half(1.0));
    float3 _2019 = fast::normalize(_961 + _1855);
    half _1955 = clamp(dot(_955, half3(_2019)), half(0.0), half(1.0));
    half _1959 = clamp(dot(half3(_1855), half3(_2019)), half(0.0), half(1.0));
    half3 _2078 = cross(_955, half3(_2019)) * half(64.0);
    half _2082 = _1633 * _1955;
    half _2085 = dot(_2078, _2078);
    half _2065 = _1612 / fma(_2082, _2082, _2085);
    half _2131 = half(1.0) - _1959;
    half _2134 = _2131 * _2131;
    half _2139 = (_2134 * _2134) * _2131;
    half _2228 = _1779 * _1955;
    half _2180 = half(12.56637096405029296875) * max(_1959 * _1959, half(6.103515625e-05));
    half _2186 = _1735 / (fma(_2228, _2228, _2085) * _2180);
    half3 _2000 = min(min(((((half3(float3(params.facet_f0)) + (_1695 * _2139)) * min(min((_2065 * _2065) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1948, _1660, _1243 * sqrt(fma(_1948 * _1948, _1656, _1650))), half(65504.0)), half(65504.0))) * _1304) * _1330) + half3(min(_2186 * (_2186 * _2180), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1757 * _2139)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1864) * half(_1864)) / fast::max(_1850, 9.9999997473787516355514526367188e-05)) * half(_1883)) * half(_1883)), float3(65504.0))) * _1948), half3(float3(65504.0)));
    out.fragColor = float4(half4((mix(half4(_1261).xyz * (mix(half4(_1285).xxx, half4(_1285).yyy, half3(float3(params.facet_f0))) * _1304), half4(_1338).xyz, half3(_1360 * half(params.facet_clearCoat))) + _1553) + _2000, half(1.0)));
    return out;
}

