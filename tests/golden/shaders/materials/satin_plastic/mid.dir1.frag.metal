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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _657 = normalize(half3(in.v_normal));
    float3 _661 = fast::normalize(in.v_toEye);
    half _815 = max(dot(_657, half3(_661)), half(9.9999997473787516355514526367188e-05));
    half3 _819 = reflect(-half3(_661), _657);
    float4 _854 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_815, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _873 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_854).y) - half(1.0)));
    float4 _883 = facet_environment.sample(facet_environmentSmplr, float3(_819), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _960 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _917 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_815, _960)), level(0.0));
    half3 _967 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1341 = half4(_917);
    half _930 = _1341.z;
    half _932 = fma(half(-float(max(_967.x, max(_967.y, _967.z)))), _930, half(1.0));
    half _976 = _960 * _960;
    float4 _991 = facet_environment.sample(facet_environmentSmplr, float3(_819), level(_960 * (half(4.0) * (half(2.0) - _960))));
    half3 _717 = half4(frame.lightDirection).xyz;
    half3 _729 = half4(frame.lightColor).xyz;
    half3 _1107 = normalize(half3(_661) + _717);
    half _1046 = clamp(dot(_657, _717), half(0.0), half(1.0));
    half _1050 = clamp(dot(_657, _1107), half(0.0), half(1.0));
    half3 _1134 = cross(_657, _1107);
    half _1137 = _1050 * half(params.facet_alpha);
    half _1151 = _1046 + _815;
    half _1154 = max(mix((half(2.0) * _1046) * _815, _1151, half(params.facet_alpha)), half(0.000244140625));
    half _1161 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1137, _1137, dot(_1134, _1134)) * (half(6433.98193359375) * _1154));
    half _1198 = half(8192.0) * fma(half(-float(_1046)), _815, _1151);
    half _1202 = half(1.0) / (_976 * _1198);
    half3 _1231 = fma(half4(_991).xyz, _967 * _930, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_883).xyz * (mix(half4(_854).xxx, half4(_854).yyy, half3(float3(params.facet_f0))) * _873)) * _932) + min(fma((half3(float3(params.facet_f0)) * min(_1161 * (_1161 * (half(6.283185482025146484375) * _1154)), half(65504.0))) * _873, (_729 * _1046) * _932, (_967 * ((((fma(_1202, _1198, half(2.0)) * pow(max(fma(half(-float(_1050)), _1050, half(1.0)), half(0.0)), half(0.5) * (_1202 * _1198))) * half(0.15915493667125701904296875)) * (_1046 * (_1202 * (half(2048.0) * _976)))) * half4(_917).w)) * _729), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1231, half(1.0)));
    return out;
}

