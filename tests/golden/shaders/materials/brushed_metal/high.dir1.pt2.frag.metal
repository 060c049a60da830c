#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _943 = normalize(half3(in.v_normal));
    float3 _949 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1105 = half4(in.v_tangent).xyz;
    half3 _1112 = _1105 - (_943 * dot(_943, _1105));
    half _1114 = _943.z;
    half3 _2437;
    if (float(abs(_1114)) < 0.5)
    {
        _2437 = half3(-_943.y, _943.x, half(0.0));
    }
    else
    {
        _2437 = half3(half(0.0), -_1114, _943.y);
    }
    half3 _1141 = normalize(half3(select(float3(_2437), float3(_1112), bool3(float(dot(_1112, _1112)) > 0.001000000047497451305389404296875))));
    half _969 = max(dot(_943, half3(_949)), half(9.9999997473787516355514526367188e-05));
    half3 _1154 = cross(_943, _1141);
    half _1205 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1200 = clamp(half2(half(1.0) + _1205, half(1.0) - _1205) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1160 = half2(float2(1.0)) / _1200;
    half2 _1162 = _1200 * half(128.0);
    half _1168 = half(0.3183098733425140380859375) * (_1160.x * _1160.y);
    half _1184 = length(half3(_1162 * half2(dot(_1141, half3(_949)), dot(_1154, half3(_949))), half(128.0) * _969));
    half3 _2453 = select(_1154, _1141, bool3(float(_1205) >= 0.0));
    half _1434 = dot(_2453, half3(_949));
    half _1441 = min(abs(_1205) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1446 = fma(half(-float(_1441)), half(1.0) - _969, half(1.0));
    half _1449 = _1441 * _1434;
    float4 _1489 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_969, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1520 = facet_environment.sample(facet_environmentSmplr, float3(((((_943 * _1446) + (_2453 * _1449)) * (half(512.0) * fma(_1446, _969, _1449 * _1434))) - (half3(_949) * (half(256.0) * fma(_1446, _1446, _1449 * _1449))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1627 = fast::normalize(_949 + frame.lightDirection.xyz);
    half _1576 = clamp(dot(_943, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1580 = clamp(dot(_943, half3(_1627)), half(0.0), half(1.0));
    half2 _1645 = half2(dot(_1141, half3(_1627)), dot(_1154, half3(_1627))) * _1160;
    half _1653 = half(1.0) / fma(_1580, _1580, dot(_1645, _1645));
    half _1694 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1627)), half(0.0), half(1.0));
    half _1697 = _1694 * _1694;
    half3 _1705 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1763 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1766 = dot(_1763, _1763);
    float3 _1771 = _1763 * rsqrt(fast::max(_1766, 9.9999999392252902907785028219223e-09));
    float _1775 = _1766 * float(frame.punctualLights[0].positionFalloff.w);
    float _1780 = fast::clamp(fma(-_1775, _1775, 1.0), 0.0, 1.0);
    float _1799 = fast::clamp(fma(dot(-_1771, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1909 = fast::normalize(_949 + _1771);
    half _1858 = clamp(dot(_943, half3(_1771)), half(0.0), half(1.0));
    half _1862 = clamp(dot(_943, half3(_1909)), half(0.0), half(1.0));
    half2 _1927 = half2(dot(_1141, half3(_1909)), dot(_1154, half3(_1909))) * _1160;
    half _1935 = half(1.0) / fma(_1862, _1862, dot(_1927, _1927));
    half _1976 = half(1.0) - clamp(dot(half3(_1771), half3(_1909)), half(0.0), half(1.0));
    half _1979 = _1976 * _1976;
    half3 _1890 = min(((half3(float3(params.facet_f0)) + (_1705 * ((_1979 * _1979) * _1976))) * min(((_1168 * _1935) * _1935) * min(half(64.0) / fma(_1858, _1184, _969 * length(half3(_1162 * half2(dot(_1141, half3(_1771)), dot(_1154, half3(_1771))), half(128.0) * _1858))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1780) * half(_1780)) / fast::max(_1766, 9.9999997473787516355514526367188e-05)) * half(_1799)) * half(_1799)), float3(65504.0))) * _1858), half3(float3(65504.0)));
    half3 _2009 = fma(half4(_1520).xyz, mix(half4(_1489).xxx, half4(_1489).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1489).y) - half(1.0)))), min(((half3(float3(params.facet_f0)) + (_1705 * ((_1697 * _1697) * _1694))) * min(((_1168 * _1653) * _1653) * min(half(64.0) / fma(_1576, _1184, _969 * length(half3(_1162 * half2(dot(_1141, half3(frame.lightDirection.xyz)), dot(_1154, half3(frame.lightDirection.xyz))), half(128.0) * _1576))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1576), half3(float3(65504.0)))) + _1890;
    float3 _2045 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2048 = dot(_2045, _2045);
    float3 _2053 = _2045 * rsqrt(fast::max(_2048, 9.9999999392252902907785028219223e-09));
    float _2057 = _2048 * float(frame.punctualLights[1].positionFalloff.w);
    float _2062 = fast::clamp(fma(-_2057, _2057, 1.0), 0.0, 1.0);
    float _2081 = fast::clamp(fma(dot(-_2053, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2191 = fast::normalize(_949 + _2053);
    half _2140 = clamp(dot(_943, half3(_2053)), half(0.0), half(1.0));
    half _2144 = clamp(dot(_943, half3(_2191)), half(0.0), half(1.0));
    half2 _2209 = half2(dot(_1141, half3(_2191)), dot(_1154, half3(_2191))) * _1160;
    half _2217 = half(1.0) / fma(_2144, _2144, dot(_2209, _2209));
    half _2258 = half(1.0) - clamp(dot(half3(_2053), half3(_2191)), half(0.0), half(1.0));
    half _2261 = _2258 * _2258;
    half3 _2172 = min(((half3(float3(params.facet_f0)) + (_1705 * ((_2261 * _2261) * _2258))) * min(((_1168 * _2217) * _2217) * min(half(64.0) / fma(_2140, _1184, _969 * length(half3(_1162 * half2(dot(_1141, half3(_2053)), dot(_1154, half3(_2053))), half(128.0) * _2140))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2062) * half(_2062)) / fast::max(_2048, 9.9999997473787516355514526367188e-05)) * half(_2081)) * half(_2081)), float3(65504.0))) * _2140), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2009 + _2172, half(1.0)));
    return out;
}

