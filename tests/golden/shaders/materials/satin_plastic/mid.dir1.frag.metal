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
    half3 _676 = normalize(half3(in.v_normal));
    float3 _680 = fast::normalize(in.v_toEye);
    half _834 = max(dot(_676, half3(_680)), half(9.9999997473787516355514526367188e-05));
    half3 _838 = reflect(-half3(_680), _676);
    float4 _873 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_834, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _892 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_873).y) - half(1.0)));
    float4 _902 = facet_environment.sample(facet_environmentSmplr, float3(_838), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _979 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _936 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_834, _979)), level(0.0));
    half3 _986 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1370 = half4(_936);
    half _949 = _1370.z;
    half _951 = fma(half(-float(max(_986.x, max(_986.y, _986.z)))), _949, half(1.0));
    half _995 = _979 * _979;
    float4 _1010 = facet_environment.sample(facet_environmentSmplr, float3(_838), level(_979 * (half(4.0) * (half(2.0) - _979))));
    half3 _736 = half4(frame.lightDirection).xyz;
    half3 _748 = half4(frame.lightColor).xyz;
    half3 _1126 = normalize(half3(_680) + _736);
    half _1065 = clamp(dot(_676, _736), half(0.0), half(1.0));
    half _1069 = clamp(dot(_676, _1126), half(0.0), half(1.0));
    half4 _1195 = half4(cross(_676, _1126), half(params.facet_alpha) * _1069) * half(64.0);
    half _1164 = _1065 + _834;
    half _1172 = half(6.283185482025146484375) * max(mix((half(2.0) * _1065) * _834, _1164, half(params.facet_alpha)), half(0.000244140625));
    half _1174 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1195, _1195) * _1172);
    half _1228 = half(8192.0) * fma(half(-float(_1065)), _834, _1164);
    half _1232 = half(1.0) / (_995 * _1228);
    half3 _1261 = fma(half4(_1010).xyz, _986 * _949, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_902).xyz * (mix(half4(_873).xxx, half4(_873).yyy, half3(float3(params.facet_f0))) * _892)) * _951) + min(fma((half3(float3(params.facet_f0)) * min(_1174 * (_1174 * _1172), half(65504.0))) * _892, (_748 * _1065) * _951, (_986 * ((((fma(_1232, _1228, half(2.0)) * pow(max(fma(half(-float(_1069)), _1069, half(1.0)), half(0.0)), half(0.5) * (_1232 * _1228))) * half(0.15915493667125701904296875)) * (_1065 * (_1232 * (half(2048.0) * _995)))) * half4(_936).w)) * _748), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1261, half(1.0)));
    return out;
}

