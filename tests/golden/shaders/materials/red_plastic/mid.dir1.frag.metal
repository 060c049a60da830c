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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _451 = normalize(half3(in.v_normal));
    float3 _455 = fast::normalize(in.v_toEye);
    half _600 = max(dot(_451, half3(_455)), half(9.9999997473787516355514526367188e-05));
    float4 _639 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_600, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _658 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_639).y) - half(1.0)));
    float4 _665 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_455), _451)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _502 = half4(frame.lightDirection).xyz;
    half3 _772 = normalize(half3(_455) + _502);
    half _723 = clamp(dot(_451, _502), half(0.0), half(1.0));
    half3 _799 = cross(_451, _772);
    half _802 = clamp(dot(_451, _772), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _819 = max(mix((half(2.0) * _723) * _600, _723 + _600, half(params.facet_alpha)), half(0.000244140625));
    half _826 = (half(1024.0) * half(params.facet_alpha)) / (fma(_802, _802, dot(_799, _799)) * (half(6433.98193359375) * _819));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_665).xyz * (mix(half4(_639).xxx, half4(_639).yyy, half3(float3(params.facet_f0))) * _658)) + min(((half3(float3(params.facet_f0)) * min(_826 * (_826 * (half(6.283185482025146484375) * _819)), half(65504.0))) * _658) * (half4(frame.lightColor).xyz * _723), half3(float3(65504.0))), half(1.0)));
    return out;
}

