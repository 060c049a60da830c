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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _500 = normalize(half3(in.v_normal));
    float3 _504 = fast::normalize(in.v_toEye);
    half _614 = _500.y;
    half _619 = _500.z;
    half _624 = _500.x;
    half3 _692 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _614)) + (half4(frame.sh[2]).xyz * _619)) + (half4(frame.sh[3]).xyz * _624)) + (((((half4(frame.sh[4]).xyz * (_624 * _614)) + (half4(frame.sh[5]).xyz * (_614 * _619))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _619, _619, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_624 * _619))) + (half4(frame.sh[8]).xyz * fma(_624, _624, half(-float(_614 * _614))))), half3(float3(0.0)));
    half _742 = max(dot(_500, half3(_504)), half(9.9999997473787516355514526367188e-05));
    half3 _746 = reflect(-half3(_504), _500);
    float4 _781 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_742, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _810 = facet_environment.sample(facet_environmentSmplr, float3(_746), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half4 _1033 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_742, half(params.facet_sheenRoughness))), level(0.0)));
    half _855 = _1033.z;
    float4 _871 = facet_environment.sample(facet_environmentSmplr, float3(_746), level(params.facet_sheenLod));
    out.fragColor = float4(half4(fma(half4(_871).xyz, half3(float3(params.facet_sheenColor)) * _855, fma(half3(float3(params.facet_diffuseColor)), _692, half4(_810).xyz * (mix(half4(_781).xxx, half4(_781).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_781).y) - half(1.0)))))) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _855, half(1.0))), half(1.0)));
    return out;
}

