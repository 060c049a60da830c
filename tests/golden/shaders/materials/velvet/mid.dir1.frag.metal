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
    half3 _403 = normalize(half3(in.v_normal));
    float3 _407 = fast::normalize(in.v_toEye);
    half _543 = max(dot(_403, half3(_407)), half(9.9999997473787516355514526367188e-05));
    float4 _548 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_543, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _602 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _817 = half4(_548);
    half _561 = _817.z;
    float4 _621 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_407), _403)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _452 = half4(frame.lightDirection).xyz;
    half _643 = clamp(dot(_403, _452), half(0.0), half(1.0));
    half _655 = clamp(dot(_403, normalize(half3(_407) + _452)), half(0.0), half(1.0));
    half _700 = half(8192.0) * fma(half(-float(_643)), _543, _643 + _543);
    half _704 = half(1.0) / (half(params.facet_alpha) * _700);
    half3 _733 = fma(half4(_621).xyz, _602 * _561, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_602.x, max(_602.y, _602.z)))), _561, half(1.0))) + min((_602 * ((((fma(_704, _700, half(2.0)) * pow(max(fma(half(-float(_655)), _655, half(1.0)), half(0.0)), half(0.5) * (_704 * _700))) * half(0.15915493667125701904296875)) * (_643 * (_704 * (half(2048.0) * half(params.facet_alpha))))) * half4(_548).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(_733, half(1.0)));
    return out;
}

