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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _384 = normalize(half3(in.v_normal));
    float3 _388 = fast::normalize(in.v_toEye);
    half _522 = max(dot(_384, half3(_388)), half(9.9999997473787516355514526367188e-05));
    float4 _527 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_522, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _783 = half4(_527);
    half _540 = _783.z;
    float4 _556 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_388), _384)), level(params.facet_sheenLod));
    half3 _433 = half4(frame.lightDirection).xyz;
    half _611 = clamp(dot(_384, _433), half(0.0), half(1.0));
    half _623 = clamp(dot(_384, normalize(half3(_388) + _433)), half(0.0), half(1.0));
    half _668 = half(8192.0) * fma(half(-float(_611)), _522, _611 + _522);
    half _672 = half(1.0) / (half(params.facet_alpha) * _668);
    half3 _701 = fma(half4(_556).xyz, half3(float3(params.facet_sheenColor)) * _540, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _540, half(1.0))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_672, _668, half(2.0)) * pow(max(fma(half(-float(_623)), _623, half(1.0)), half(0.0)), half(0.5) * (_672 * _668))) * half(0.15915493667125701904296875)) * (_611 * (_672 * (half(2048.0) * half(params.facet_alpha))))) * half4(_527).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(_701, half(1.0)));
    return out;
}

