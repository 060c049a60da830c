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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _643 = normalize(half3(in.v_normal));
    float3 _647 = fast::normalize(in.v_toEye);
    half _800 = max(dot(_643, half3(_647)), half(9.9999997473787516355514526367188e-05));
    half3 _804 = reflect(-half3(_647), _643);
    float4 _833 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_800, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _852 = facet_environment.sample(facet_environmentSmplr, float3(_804), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _884 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_800, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1279 = half4(_884);
    half _897 = _1279.z;
    half _899 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _897, half(1.0));
    float4 _913 = facet_environment.sample(facet_environmentSmplr, float3(_804), level(params.facet_sheenLod));
    half3 _703 = half4(frame.lightDirection).xyz;
    half3 _715 = half4(frame.lightColor).xyz;
    half3 _1049 = normalize(half3(_647) + _703);
    half _991 = clamp(dot(_643, _703), half(0.0), half(1.0));
    half _995 = clamp(dot(_643, _1049), half(0.0), half(1.0));
    half4 _1118 = half4(cross(_643, _1049), half(params.facet_alpha) * _995) * half(64.0);
    half _1087 = _991 + _800;
    half _1095 = half(6.283185482025146484375) * max(mix((half(2.0) * _991) * _800, _1087, half(params.facet_alpha)), half(0.000244140625));
    half _1097 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1118, _1118) * _1095);
    half _1151 = half(8192.0) * fma(half(-float(_991)), _800, _1087);
    half _1155 = half(1.0) / (half(params.facet_sheenAlpha) * _1151);
    half3 _1184 = fma(half4(_913).xyz, half3(float3(params.facet_sheenColor)) * _897, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_852).xyz * mix(half4(_833).xxx, half4(_833).yyy, half3(float3(params.facet_f0)))) * _899) + min(fma(half3(float3(params.facet_f0)) * min(_1097 * (_1097 * _1095), half(65504.0)), (_715 * _991) * _899, (half3(float3(params.facet_sheenColor)) * ((((fma(_1155, _1151, half(2.0)) * pow(max(fma(half(-float(_995)), _995, half(1.0)), half(0.0)), half(0.5) * (_1155 * _1151))) * half(0.15915493667125701904296875)) * (_991 * (_1155 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_884).w)) * _715), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1184, half(1.0)));
    return out;
}

