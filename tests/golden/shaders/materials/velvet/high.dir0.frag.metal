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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _378 = normalize(half3(in.v_normal));
    float3 _382 = fast::normalize(in.v_toEye);
    half _481 = _378.y;
    half _486 = _378.z;
    half _491 = _378.x;
    half3 _559 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _481)) + (half4(frame.sh[2]).xyz * _486)) + (half4(frame.sh[3]).xyz * _491)) + (((((half4(frame.sh[4]).xyz * (_491 * _481)) + (half4(frame.sh[5]).xyz * (_481 * _486))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _486, _486, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_491 * _486))) + (half4(frame.sh[8]).xyz * fma(_491, _491, half(-float(_481 * _481))))), half3(float3(0.0)));
    half3 _655 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _783 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_378, half3(_382)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _617 = _783.z;
    float4 _662 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_382), _378)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(half4(_662).xyz, _655 * _617, (half3(float3(params.facet_diffuseColor)) * _559) * fma(half(-float(max(_655.x, max(_655.y, _655.z)))), _617, half(1.0))), half(1.0)));
    return out;
}

