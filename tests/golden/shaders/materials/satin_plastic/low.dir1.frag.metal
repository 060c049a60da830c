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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _623 = normalize(half3(in.v_normal));
    half3 _730 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _794 = max(dot(_623, _730), half(9.9999997473787516355514526367188e-05));
    half3 _798 = reflect(-_730, _623);
    float4 _828 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_794, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _837 = mix(half4(_828).xxx, half4(_828).yyy, half3(float3(params.facet_f0)));
    float4 _847 = facet_environment.sample(facet_environmentSmplr, float3(_798), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _879 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_794, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1249 = half4(_879);
    half _892 = _1249.z;
    half _894 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _892, half(1.0));
    float4 _908 = facet_environment.sample(facet_environmentSmplr, float3(_798), level(params.facet_sheenLod));
    half3 _684 = half4(frame.lightDirection).xyz;
    half3 _696 = half4(frame.lightColor).xyz;
    half _986 = clamp(dot(_623, _684), half(0.0), half(1.0));
    half _990 = clamp(dot(_623, normalize(_730 + _684)), half(0.0), half(1.0));
    half _1069 = clamp(dot(_798, _684), half(0.0), half(1.0));
    half _1072 = _1069 * _1069;
    half4 _1270 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1072 * _1072, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1084 = _1270.x;
    half _1118 = half(8192.0) * fma(half(-float(_986)), _794, _986 + _794);
    half _1122 = half(1.0) / (half(params.facet_sheenAlpha) * _1118);
    half3 _1151 = fma(half4(_908).xyz, half3(float3(params.facet_sheenColor)) * _892, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_847).xyz * _837) * _894) + min(fma(_837 * ((_1084 * _1084) * half(5.092957973480224609375)), (_696 * _986) * _894, (half3(float3(params.facet_sheenColor)) * ((((fma(_1122, _1118, half(2.0)) * pow(max(fma(half(-float(_990)), _990, half(1.0)), half(0.0)), half(0.5) * (_1122 * _1118))) * half(0.15915493667125701904296875)) * (_986 * (_1122 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_879).w)) * _696), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1151, half(1.0)));
    return out;
}

