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
    half _1270 = max(dot(_960, half3(_966)), half(9.9999997473787516355514526367188e-05));
    half3 _1274 = reflect(-half3(_966), _960);
    float4 _1309 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1270, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1328 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1309).y) - half(1.0)));
    float4 _1335 = facet_environment.sample(facet_environmentSmplr, float3(_1274), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1383 = half(1.0) - _1270;
    half _1386 = _1383 * _1383;
    half _1393 = fma(half(0.959999978542327880859375), (_1386 * _1386) * _1383, half(0.039999999105930328369140625));
    half _1398 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1365 = fma(half(-float(_1393)), _1398, half(1.0));
    half _1403 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1410 = facet_environment.sample(facet_environmentSmplr, float3(_1274), level(_1403 * half(4.0)));
    float3 _1535 = fast::normalize(_966 + frame.lightDirection.xyz);
    half _1468 = clamp(dot(_960, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1472 = clamp(dot(_960, half3(_1535)), half(0.0), half(1.0));
    half _1476 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1535)), half(0.0), half(1.0));
    half3 _1575 = cross(_960, half3(_1535));
    half _1578 = _1472 * half(params.facet_alpha);
    half _1587 = half(params.facet_alpha) / fma(_1578, _1578, dot(_1575, _1575));
    half _1601 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1607 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1611 = sqrt(fma(_1270 * _1270, _1607, _1601));
    half _1635 = half(1.0) - _1476;
    half _1638 = _1635 * _1635;
    half _1643 = (_1638 * _1638) * _1635;
    half3 _1646 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1494 = half4(frame.lightColor).xyz * _1468;
    half _1680 = _1403 * _1403;
    half3 _1684 = _1575 * half(64.0);
    half _1687 = half(64.0) * _1680;
    half _1688 = _1472 * _1687;
    half _1700 = half(12.56637096405029296875) * max(_1476 * _1476, half(6.103515625e-05));
    half _1702 = half(4096.0) * _1680;
    half _1706 = _1702 / (fma(_1688, _1688, dot(_1684, _1684)) * _1700);
    float3 _1805 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1808 = dot(_1805, _1805);
    float3 _1813 = _1805 * rsqrt(fast::max(_1808, 9.9999999392252902907785028219223e-09));
    float _1817 = _1808 * float(frame.punctualLights[0].positionFalloff.w);
    float _1822 = fast::clamp(fma(-_1817, _1817, 1.0), 0.0, 1.0);
    float _1841 = fast::clamp(fma(dot(-_1813, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1977 = fast::normalize(_966 + _1813);
    half _1910 = clamp(dot(_960, half3(_1813)), half(0.0), half(1.0));
    half _1914 = clamp(dot(_960, half3(_1977)), half(0.0), half(1.0));
    half _1918 = clamp(dot(half3(_1813), half3(_1977)), half(0.0), half(1.0));
    half3 _2017 = cross(_960, half3(_1977));
    half _2020 = _1914 * half(params.facet_alpha);
    half _2029 = half(params.facet_alpha) / fma(_2020, _2020, dot(_2017, _2017));
    half _2077 = half(1.0) - _1918;
    half _2080 = _2077 * _2077;
    half _2085 = (_2080 * _2080) * _2077;
    half3 _1936 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1822) * half(_1822)) / fast::max(_1808, 9.9999997473787516355514526367188e-05)) * half(_1841)) * half(_1841)), float3(65504.0))) * _1910;
    half3 _2126 = _2017 * half(64.0);
    half _2130 = _1914 * _1687;
    half _2142 = half(12.56637096405029296875) * max(_1918 * _1918, half(6.103515625e-05));
    half _2148 = _1702 / (fma(_2130, _2130, dot(_2126, _2126)) * _2142);
    half3 _2211 = (mix(half4(_1335).xyz * (mix(half4(_1309).xxx, half4(_1309).yyy, half3(float3(params.facet_f0))) * _1328), half4(_1410).xyz, half3(_1393 * _1398)) + min(fma(((half3(float3(params.facet_f0)) + (_1646 * _1643)) * min(min((_1587 * _1587) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1468, _1611, _1270 * sqrt(fma(_1468 * _1468, _1607, _1601))), half(65504.0)), half(65504.0))) * _1328, _1494 * _1365, _1494 * (min(_1706 * (_1706 * _1700), half(65504.0)) * (fma(half(0.959999978542327880859375), _1643, half(0.039999999105930328369140625)) * _1398))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1646 * _2085)) * min(min((_2029 * _2029) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1910, _1611, _1270 * sqrt(fma(_1910 * _1910, _1607, _1601))), half(65504.0)), half(65504.0))) * _1328, _1936 * _1365, _1936 * (min(_2148 * (_2148 * _2142), half(65504.0)) * (fma(half(0.959999978542327880859375), _2085, half(0.039999999105930328369140625)) * _1398))), half3(float3(65504.0)));
    float3 _2247 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2250 = dot(_2247, _2247);
    float3 _2255 = _2247 * rsqrt(fast::max(_2250, 9.9999999392252902907785028219223e-09));
    float _2259 = _2250 * float(frame.punctualLights[1].positionFalloff.w);
    float _2264 = fast::clamp(fma(-_2259, _2259, 1.0), 0.0, 1.0);
    float _2283 = fast::clamp(fma(dot(-_2255, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2419 = fast::normalize(_966 + _2255);
    half _2352 = clamp(dot(_960, half3(_2255)), half(0.0), half(1.0));
    half _2356 = clamp(dot(_960, half3(_2419)), half(0.0), half(1.0));
    half _2360 = clamp(dot(half3(_2255), half3(_2419)), half(0.0), half(1.0));
    half3 _2459 = cross(_960, half3(_2419));
    half _2462 = _2356 * half(params.facet_alpha);
    half _2471 = half(params.facet_alpha) / fma(_2462, _2462, dot(_2459, _2459));
    half _2519 = half(1.0) - _2360;
    half _2522 = _2519 * _2519;
    half _2527 = (_2522 * _2522) * _2519;
    half3 _2378 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2264) * half(_2264)) / fast::max(_2250, 9.9999997473787516355514526367188e-05)) * half(_2283)) * half(_2283)), float3(65504.0))) * _2352;
    half3 _2568 = _2459 * half(64.0);
    half _2572 = _2356 * _1687;
    half _2584 = half(12.56637096405029296875) * max(_2360 * _2360, half(6.103515625e-05));
    half _2590 = _1702 / (fma(_2572, _2572, dot(_2568, _2568)) * _2584);
    out.fragColor = float4(half4(_2211 + min(fma(((half3(float3(params.facet_f0)) + (_1646 * _2527)) * min(min((_2471 * _2471) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2352, _1611, _1270 * sqrt(fma(_2352 * _2352, _1607, _1601))), half(65504.0)), half(65504.0))) * _1328, _2378 * _1365, _2378 * (min(_2590 * (_2590 * _2584), half(65504.0)) * (fma(half(0.959999978542327880859375), _2527, half(0.039999999105930328369140625)) * _1398))), half3(float3(65504.0))), half(1.0)));
    return out;
}

