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
    half3 _958 = normalize(half3(in.v_normal));
    float3 _964 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1247 = max(dot(_958, half3(_964)), half(9.9999997473787516355514526367188e-05));
    half3 _1251 = reflect(-half3(_964), _958);
    float4 _1286 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1247, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1305 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1286).y) - half(1.0)));
    float4 _1312 = facet_environment.sample(facet_environmentSmplr, float3(_1251), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1360 = half(1.0) - _1247;
    half _1363 = _1360 * _1360;
    half _1370 = fma(half(0.959999978542327880859375), (_1363 * _1363) * _1360, half(0.039999999105930328369140625));
    half _1375 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1342 = fma(half(-float(_1370)), _1375, half(1.0));
    half _1380 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1387 = facet_environment.sample(facet_environmentSmplr, float3(_1251), level(_1380 * half(4.0)));
    float3 _1424 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1427 = dot(_1424, _1424);
    float3 _1432 = _1424 * rsqrt(fast::max(_1427, 9.9999999392252902907785028219223e-09));
    float _1436 = _1427 * float(frame.punctualLights[0].positionFalloff.w);
    float _1441 = fast::clamp(fma(-_1436, _1436, 1.0), 0.0, 1.0);
    float _1460 = fast::clamp(fma(dot(-_1432, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1596 = fast::normalize(_964 + _1432);
    half _1529 = clamp(dot(_958, half3(_1432)), half(0.0), half(1.0));
    half _1533 = clamp(dot(_958, half3(_1596)), half(0.0), half(1.0));
    half _1537 = clamp(dot(half3(_1432), half3(_1596)), half(0.0), half(1.0));
    half3 _1636 = cross(_958, half3(_1596));
    half _1639 = _1533 * half(params.facet_alpha);
    half _1643 = dot(_1636, _1636);
    half _1648 = half(params.facet_alpha) / fma(_1639, _1639, _1643);
    half _1662 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1668 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1672 = sqrt(fma(_1247 * _1247, _1668, _1662));
    half _1696 = half(1.0) - _1537;
    half _1699 = _1696 * _1696;
    half _1704 = (_1699 * _1699) * _1696;
    half3 _1707 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1555 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1441) * half(_1441)) / fast::max(_1427, 9.9999997473787516355514526367188e-05)) * half(_1460)) * half(_1460)), float3(65504.0))) * _1529;
    half _1741 = _1380 * _1380;
    half _1747 = _1533 * _1741;
    half _1758 = max(_1537 * _1537, half(6.103515625e-05));
    half _1761 = half(2048.0) * _1741;
    half _1766 = _1761 / (fma(_1747, _1747, _1643) * (_1758 * half(25735.927734375)));
    float3 _1865 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1868 = dot(_1865, _1865);
    float3 _1873 = _1865 * rsqrt(fast::max(_1868, 9.9999999392252902907785028219223e-09));
    float _1877 = _1868 * float(frame.punctualLights[1].positionFalloff.w);
    float _1882 = fast::clamp(fma(-_1877, _1877, 1.0), 0.0, 1.0);
    float _1901 = fast::clamp(fma(dot(-_1873, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2037 = fast::normalize(_964 + _1873);
    half _1970 = clamp(dot(_958, half3(_1873)), half(0.0), half(1.0));
    half _1974 = clamp(dot(_958, half3(_2037)), half(0.0), half(1.0));
    half _1978 = clamp(dot(half3(_1873), half3(_2037)), half(0.0), half(1.0));
    half3 _2077 = cross(_958, half3(_2037));
    half _2080 = _1974 * half(params.facet_alpha);
    half _2084 = dot(_2077, _2077);
    half _2089 = half(params.facet_alpha) / fma(_2080, _2080, _2084);
    half _2137 = half(1.0) - _1978;
    half _2140 = _2137 * _2137;
    half _2145 = (_2140 * _2140) * _2137;
    half3 _1996 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1882) * half(_1882)) / fast::max(_1868, 9.9999997473787516355514526367188e-05)) * half(_1901)) * half(_1901)), float3(65504.0))) * _1970;
    half _2188 = _1974 * _1741;
    half _2199 = max(_1978 * _1978, half(6.103515625e-05));
    half _2207 = _1761 / (fma(_2188, _2188, _2084) * (_2199 * half(25735.927734375)));
    half3 _2270 = (mix(half4(_1312).xyz * (mix(half4(_1286).xxx, half4(_1286).yyy, half3(float3(params.facet_f0))) * _1305), half4(_1387).xyz, half3(_1370 * _1375)) + min(fma(((half3(float3(params.facet_f0)) + (_1707 * _1704)) * min(min((_1648 * _1648) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1529, _1672, _1247 * sqrt(fma(_1529 * _1529, _1668, _1662))), half(65504.0)), half(65504.0))) * _1305, _1555 * _1342, _1555 * (min(_1766 * (_1766 * (half(12.56637096405029296875) * _1758)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1704, half(0.039999999105930328369140625)) * _1375))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1707 * _2145)) * min(min((_2089 * _2089) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1970, _1672, _1247 * sqrt(fma(_1970 * _1970, _1668, _1662))), half(65504.0)), half(65504.0))) * _1305, _1996 * _1342, _1996 * (min(_2207 * (_2207 * (half(12.56637096405029296875) * _2199)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2145, half(0.039999999105930328369140625)) * _1375))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2270, half(1.0)));
    return out;
}

