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
    half3 _960 = normalize(half3(in.v_normal));
    float3 _966 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1249 = max(dot(_960, half3(_966)), half(9.9999997473787516355514526367188e-05));
    half3 _1253 = reflect(-half3(_966), _960);
    float4 _1288 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1249, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1307 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1288).y) - half(1.0)));
    float4 _1314 = facet_environment.sample(facet_environmentSmplr, float3(_1253), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1362 = half(1.0) - _1249;
    half _1365 = _1362 * _1362;
    half _1372 = fma(half(0.959999978542327880859375), (_1365 * _1365) * _1362, half(0.039999999105930328369140625));
    half _1377 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1344 = fma(half(-float(_1372)), _1377, half(1.0));
    half _1382 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1389 = facet_environment.sample(facet_environmentSmplr, float3(_1253), level(_1382 * half(4.0)));
    float3 _1426 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1429 = dot(_1426, _1426);
    float3 _1434 = _1426 * rsqrt(fast::max(_1429, 9.9999999392252902907785028219223e-09));
    float _1438 = _1429 * float(frame.punctualLights[0].positionFalloff.w);
    float _1443 = fast::clamp(fma(-_1438, _1438, 1.0), 0.0, 1.0);
    float _1462 = fast::clamp(fma(dot(-_1434, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1598 = fast::normalize(_966 + _1434);
    half _1531 = clamp(dot(_960, half3(_1434)), half(0.0), half(1.0));
    half _1535 = clamp(dot(_960, half3(_1598)), half(0.0), half(1.0));
    half _1539 = clamp(dot(half3(_1434), half3(_1598)), half(0.0), half(1.0));
    half3 _1638 = cross(_960, half3(_1598));
    half _1641 = _1535 * half(params.facet_alpha);
    half _1650 = half(params.facet_alpha) / fma(_1641, _1641, dot(_1638, _1638));
    half _1664 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1670 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1674 = sqrt(fma(_1249 * _1249, _1670, _1664));
    half _1698 = half(1.0) - _1539;
    half _1701 = _1698 * _1698;
    half _1706 = (_1701 * _1701) * _1698;
    half3 _1709 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1557 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1443) * half(_1443)) / fast::max(_1429, 9.9999997473787516355514526367188e-05)) * half(_1462)) * half(_1462)), float3(65504.0))) * _1531;
    half _1743 = _1382 * _1382;
    half3 _1747 = _1638 * half(64.0);
    half _1750 = half(64.0) * _1743;
    half _1751 = _1535 * _1750;
    half _1763 = half(12.56637096405029296875) * max(_1539 * _1539, half(6.103515625e-05));
    half _1765 = half(4096.0) * _1743;
    half _1769 = _1765 / (fma(_1751, _1751, dot(_1747, _1747)) * _1763);
    float3 _1868 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1871 = dot(_1868, _1868);
    float3 _1876 = _1868 * rsqrt(fast::max(_1871, 9.9999999392252902907785028219223e-09));
    float _1880 = _1871 * float(frame.punctualLights[1].positionFalloff.w);
    float _1885 = fast::clamp(fma(-_1880, _1880, 1.0), 0.0, 1.0);
    float _1904 = fast::clamp(fma(dot(-_1876, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2040 = fast::normalize(_966 + _1876);
    half _1973 = clamp(dot(_960, half3(_1876)), half(0.0), half(1.0));
    half _1977 = clamp(dot(_960, half3(_2040)), half(0.0), half(1.0));
    half _1981 = clamp(dot(half3(_1876), half3(_2040)), half(0.0), half(1.0));
    half3 _2080 = cross(_960, half3(_2040));
    half _2083 = _1977 * half(params.facet_alpha);
    half _2092 = half(params.facet_alpha) / fma(_2083, _2083, dot(_2080, _2080));
    half _2140 = half(1.0) - _1981;
    half _2143 = _2140 * _2140;
    half _2148 = (_2143 * _2143) * _2140;
    half3 _1999 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1885) * half(_1885)) / fast::max(_1871, 9.9999997473787516355514526367188e-05)) * half(_1904)) * half(_1904)), float3(65504.0))) * _1973;
    half3 _2189 = _2080 * half(64.0);
    half _2193 = _1977 * _1750;
    half _2205 = half(12.56637096405029296875) * max(_1981 * _1981, half(6.103515625e-05));
    half _2211 = _1765 / (fma(_2193, _2193, dot(_2189, _2189)) * _2205);
    half3 _2274 = (mix(half4(_1314).xyz * (mix(half4(_1288).xxx, half4(_1288).yyy, half3(float3(params.facet_f0))) * _1307), half4(_1389).xyz, half3(_1372 * _1377)) + min(fma(((half3(float3(params.facet_f0)) + (_1709 * _1706)) * min(min((_1650 * _1650) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1531, _1674, _1249 * sqrt(fma(_1531 * _1531, _1670, _1664))), half(65504.0)), half(65504.0))) * _1307, _1557 * _1344, _1557 * (min(_1769 * (_1769 * _1763), half(65504.0)) * (fma(half(0.959999978542327880859375), _1706, half(0.039999999105930328369140625)) * _1377))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1709 * _2148)) * min(min((_2092 * _2092) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1973, _1674, _1249 * sqrt(fma(_1973 * _1973, _1670, _1664))), half(65504.0)), half(65504.0))) * _1307, _1999 * _1344, _1999 * (min(_2211 * (_2211 * _2205), half(65504.0)) * (fma(half(0.959999978542327880859375), _2148, half(0.039999999105930328369140625)) * _1377))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2274, half(1.0)));
    return out;
}

