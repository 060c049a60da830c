#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _457 = normalize(half3(in.v_normal));
    half3 _552 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _584 = facet_irradiance.sample(facet_irradianceSmplr, float3(_457), level(0.0));
    half _624 = max(dot(_457, _552), half(9.9999997473787516355514526367188e-05));
    float4 _629 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_624, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _939 = half4(_629);
    half _642 = _939.z;
    half _644 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _642, half(1.0));
    float4 _658 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_552, _457)), level(params.facet_sheenLod));
    half3 _504 = half4(frame.lightDirection).xyz;
    half _714 = dot(_457, _504);
    half _716 = clamp(_714, half(0.0), half(1.0));
    half _728 = clamp(dot(_457, normalize(_552 + _504)), half(0.0), half(1.0));
    half _797 = half(8192.0) * fma(half(-float(_716)), _624, _716 + _624);
    half _801 = half(1.0) / (half(params.facet_alpha) * _797);
    half3 _761 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_714 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_716), half3(float3(0.0)), half3(float3(1.0)))) * _644) + (half3(float3(params.facet_sheenColor)) * ((((fma(_801, _797, half(2.0)) * pow(max(fma(half(-float(_728)), _728, half(1.0)), half(0.0)), half(0.5) * (_801 * _797))) * half(0.15915493667125701904296875)) * (_716 * (_801 * (half(2048.0) * half(params.facet_alpha))))) * half4(_629).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    half3 _836 = fma(half4(_658).xyz, half3(float3(params.facet_sheenColor)) * _642, (half3(float3(params.facet_diffuseColor)) * half4(_584).xyz) * _644) + _761;
    out.fragColor = float4(half4(_836, half(1.0)));
    return out;
}

