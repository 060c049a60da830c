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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _507 = normalize(half3(in.v_normal));
    float3 _511 = fast::normalize(in.v_toEye);
    half _620 = _507.y;
    half _625 = _507.z;
    half _630 = _507.x;
    half3 _698 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _620)) + (half4(frame.sh[2]).xyz * _625)) + (half4(frame.sh[3]).xyz * _630)) + (((((half4(frame.sh[4]).xyz * (_630 * _620)) + (half4(frame.sh[5]).xyz * (_620 * _625))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _625, _625, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_630 * _625))) + (half4(frame.sh[8]).xyz * fma(_630, _630, half(-float(_620 * _620))))), half3(float3(0.0)));
    half _748 = max(dot(_507, half3(_511)), half(9.9999997473787516355514526367188e-05));
    half3 _752 = reflect(-half3(_511), _507);
    float4 _787 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_748, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _816 = facet_environment.sample(facet_environmentSmplr, float3(_752), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _893 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    half3 _900 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1069 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_748, _893)), level(0.0)));
    half _863 = _1069.z;
    float4 _924 = facet_environment.sample(facet_environmentSmplr, float3(_752), level(_893 * (half(4.0) * (half(2.0) - _893))));
    out.fragColor = float4(half4(fma(half4(_924).xyz, _900 * _863, fma(half3(float3(params.facet_diffuseColor)), _698, half4(_816).xyz * (mix(half4(_787).xxx, half4(_787).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_787).y) - half(1.0)))))) * fma(half(-float(max(_900.x, max(_900.y, _900.z)))), _863, half(1.0))), half(1.0)));
    return out;
}

