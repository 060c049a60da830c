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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _839 = normalize(half3(in.v_normal));
    float3 _843 = fast::normalize(in.v_toEye);
    half3 _962 = half4(in.v_tangent).xyz;
    half3 _969 = _962 - (_839 * dot(_839, _962));
    half _971 = _839.z;
    half3 _1675;
    if (float(abs(_971)) < 0.5)
    {
        _1675 = half3(-_839.y, _839.x, half(0.0));
    }
    else
    {
        _1675 = half3(half(0.0), -_971, _839.y);
    }
    half3 _998 = normalize(half3(select(float3(_1675), float3(_969), bool3(float(dot(_969, _969)) > 0.001000000047497451305389404296875))));
    half _863 = max(dot(_839, half3(_843)), half(9.9999997473787516355514526367188e-05));
    half3 _1011 = cross(_839, _998);
    half _1062 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1057 = clamp(half2(half(1.0) + _1062, half(1.0) - _1062) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1017 = half2(float2(1.0)) / _1057;
    half2 _1019 = _1057 * half(128.0);
    half3 _1689 = select(_1011, _998, bool3(float(_1062) >= 0.0));
    half _1291 = dot(_1689, half3(_843));
    half _1298 = min(abs(_1062) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1303 = fma(half(-float(_1298)), half(1.0) - _863, half(1.0));
    half _1306 = _1298 * _1291;
    float4 _1346 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_863, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1375 = facet_environment.sample(facet_environmentSmplr, float3(((((_839 * _1303) + (_1689 * _1306)) * (half(512.0) * fma(_1303, _863, _1306 * _1291))) - (half3(_843) * (half(256.0) * fma(_1303, _1303, _1306 * _1306))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1482 = fast::normalize(_843 + frame.lightDirection.xyz);
    half _1431 = clamp(dot(_839, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1435 = clamp(dot(_839, half3(_1482)), half(0.0), half(1.0));
    half2 _1500 = half2(dot(_998, half3(_1482)), dot(_1011, half3(_1482))) * _1017;
    half _1508 = half(1.0) / fma(_1435, _1435, dot(_1500, _1500));
    half _1549 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1482)), half(0.0), half(1.0));
    half _1552 = _1549 * _1549;
    half3 _1463 = min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1552 * _1552) * _1549))) * min((((half(0.3183098733425140380859375) * (_1017.x * _1017.y)) * _1508) * _1508) * min(half(64.0) / fma(_1431, length(half3(_1019 * half2(dot(_998, half3(_843)), dot(_1011, half3(_843))), half(128.0) * _863)), _863 * length(half3(_1019 * half2(dot(_998, half3(frame.lightDirection.xyz)), dot(_1011, half3(frame.lightDirection.xyz))), half(128.0) * _1431))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1431), half3(float3(65504.0)));
    half3 _1582 = fma(half4(_1375).xyz, mix(half4(_1346).xxx, half4(_1346).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1346).y) - half(1.0)))), _1463);
    out.fragColor = float4(half4(_1582, half(1.0)));
    return out;
}

