#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _392 = normalize(half3(in.v_normal));
    float3 _396 = fast::normalize(in.v_toEye);
    half _493 = _392.y;
    half _498 = _392.z;
    half _503 = _392.x;
    half3 _571 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _493)) + (half4(frame.sh[2]).xyz * _498)) + (half4(frame.sh[3]).xyz * _503)) + (((((half4(frame.sh[4]).xyz * (_503 * _493)) + (half4(frame.sh[5]).xyz * (_493 * _498))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _498, _498, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_503 * _498))) + (half4(frame.sh[8]).xyz * fma(_503, _503, half(-float(_493 * _493))))), half3(float3(0.0)));
    float4 _660 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_392, half3(_396)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _686 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_396), _392)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), _571, half4(_686).xyz * (mix(half4(_660).xxx, half4(_660).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_660).y) - half(1.0)))))), half(1.0)));
    return out;
}

