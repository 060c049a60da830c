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
    half3 _835 = normalize(half3(in.v_normal));
    float3 _839 = fast::normalize(in.v_toEye);
    half3 _958 = half4(in.v_tangent).xyz;
    half3 _965 = _958 - (_835 * dot(_835, _958));
    half _967 = _835.z;
    half3 _1668;
    if (float(abs(_967)) < 0.5)
    {
        _1668 = half3(-_835.y, _835.x, half(0.0));
    }
    else
    {
        _1668 = half3(half(0.0), -_967, _835.y);
    }
    half3 _994 = normalize(half3(select(float3(_1668), float3(_965), bool3(float(dot(_965, _965)) > 0.001000000047497451305389404296875))));
    half _859 = max(dot(_835, half3(_839)), half(9.9999997473787516355514526367188e-05));
    half3 _1007 = cross(_835, _994);
    half _1058 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1053 = clamp(half2(half(1.0) + _1058, half(1.0) - _1058) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1013 = half2(float2(1.0)) / _1053;
    half2 _1015 = _1053 * half(128.0);
    half3 _1682 = select(_1007, _994, bool3(float(_1058) >= 0.0));
    half _1287 = dot(_1682, half3(_839));
    half _1294 = min(abs(_1058) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1299 = fma(half(-float(_1294)), half(1.0) - _859, half(1.0));
    half _1302 = _1294 * _1287;
    float4 _1342 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_859, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1368 = facet_environment.sample(facet_environmentSmplr, float3(((((_835 * _1299) + (_1682 * _1302)) * (half(512.0) * fma(_1299, _859, _1302 * _1287))) - (half3(_839) * (half(256.0) * fma(_1299, _1299, _1302 * _1302))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1475 = fast::normalize(_839 + frame.lightDirection.xyz);
    half _1424 = clamp(dot(_835, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1428 = clamp(dot(_835, half3(_1475)), half(0.0), half(1.0));
    half2 _1493 = half2(dot(_994, half3(_1475)), dot(_1007, half3(_1475))) * _1013;
    half _1501 = half(1.0) / fma(_1428, _1428, dot(_1493, _1493));
    half _1542 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1475)), half(0.0), half(1.0));
    half _1545 = _1542 * _1542;
    half3 _1456 = min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1545 * _1545) * _1542))) * min((((half(0.3183098733425140380859375) * (_1013.x * _1013.y)) * _1501) * _1501) * min(half(64.0) / fma(_1424, length(half3(_1015 * half2(dot(_994, half3(_839)), dot(_1007, half3(_839))), half(128.0) * _859)), _859 * length(half3(_1015 * half2(dot(_994, half3(frame.lightDirection.xyz)), dot(_1007, half3(frame.lightDirection.xyz))), half(128.0) * _1424))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1424), half3(float3(65504.0)));
    half3 _1575 = fma(half4(_1368).xyz, mix(half4(_1342).xxx, half4(_1342).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1342).y) - half(1.0)))), _1456);
    out.fragColor = float4(half4(_1575, half(1.0)));
    return out;
}

