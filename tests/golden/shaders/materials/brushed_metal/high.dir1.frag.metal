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
    half3 _959 = half4(in.v_tangent).xyz;
    half3 _966 = _959 - (_835 * dot(_835, _959));
    half _968 = _835.z;
    half3 _1669;
    if (float(abs(_968)) < 0.5)
    {
        _1669 = half3(-_835.y, _835.x, half(0.0));
    }
    else
    {
        _1669 = half3(half(0.0), -_968, _835.y);
    }
    half3 _995 = normalize(half3(select(float3(_1669), float3(_966), bool3(float(dot(_966, _966)) > 0.001000000047497451305389404296875))));
    half _859 = max(dot(_835, half3(_839)), half(9.9999997473787516355514526367188e-05));
    half3 _1008 = cross(_835, _995);
    half _1059 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1054 = clamp(half2(half(1.0) + _1059, half(1.0) - _1059) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1014 = half2(float2(1.0)) / _1054;
    half2 _1016 = _1054 * half(128.0);
    half3 _1683 = select(_1008, _995, bool3(float(_1059) >= 0.0));
    half _1288 = dot(_1683, half3(_839));
    half _1295 = min(abs(_1059) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1300 = fma(half(-float(_1295)), half(1.0) - _859, half(1.0));
    half _1303 = _1295 * _1288;
    float4 _1343 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_859, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1369 = facet_environment.sample(facet_environmentSmplr, float3(((((_835 * _1300) + (_1683 * _1303)) * (half(512.0) * fma(_1300, _859, _1303 * _1288))) - (half3(_839) * (half(256.0) * fma(_1300, _1300, _1303 * _1303))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1476 = fast::normalize(_839 + frame.lightDirection.xyz);
    half _1425 = clamp(dot(_835, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1429 = clamp(dot(_835, half3(_1476)), half(0.0), half(1.0));
    half2 _1494 = half2(dot(_995, half3(_1476)), dot(_1008, half3(_1476))) * _1014;
    half _1502 = half(1.0) / fma(_1429, _1429, dot(_1494, _1494));
    half _1543 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1476)), half(0.0), half(1.0));
    half _1546 = _1543 * _1543;
    half3 _1457 = min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1546 * _1546) * _1543))) * min((((half(0.3183098733425140380859375) * (_1014.x * _1014.y)) * _1502) * _1502) * min(half(64.0) / fma(_1425, length(half3(_1016 * half2(dot(_995, half3(_839)), dot(_1008, half3(_839))), half(128.0) * _859)), _859 * length(half3(_1016 * half2(dot(_995, half3(frame.lightDirection.xyz)), dot(_1008, half3(frame.lightDirection.xyz))), half(128.0) * _1425))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1425), half3(float3(65504.0)));
    half3 _1576 = fma(half4(_1369).xyz, mix(half4(_1343).xxx, half4(_1343).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1343).y) - half(1.0)))), _1457);
    out.fragColor = float4(half4(_1576, half(1.0)));
    return out;
}

