#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _531 = normalize(half3(in.v_normal));
    float3 _548 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _657 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _765 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _657)), half(0.0), half(1.0));
    half3 _773 = half3((half(0.1599999964237213134765625) * _765) * _765);
    half _782 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _657)), half(0.08900000154972076416015625), half(1.0));
    half _725 = max(dot(_531, half3(_548)), half(9.9999997473787516355514526367188e-05));
    float4 _789 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_725, _782)), level(0.0));
    half3 _808 = half3(float3(1.0)) + (_773 * ((half(1.0) / half4(_789).y) - half(1.0)));
    float4 _815 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_548), _531)), level(_782 * half(4.0)));
    half3 _585 = half4(frame.lightDirection).xyz;
    half _946 = _782 * _782;
    half3 _957 = normalize(half3(_548) + _585);
    half _873 = clamp(dot(_531, _585), half(0.0), half(1.0));
    half3 _984 = cross(_531, _957);
    half _987 = clamp(dot(_531, _957), half(0.0), half(1.0)) * _946;
    half _1004 = max(mix((half(2.0) * _873) * _725, _873 + _725, _946), half(0.000244140625));
    half _1011 = (half(1024.0) * _946) / (fma(_987, _987, dot(_984, _984)) * (half(6433.98193359375) * _1004));
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_657))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_815).xyz * (mix(half4(_789).xxx, half4(_789).yyy, _773) * _808)) + min(((_773 * min(_1011 * (_1011 * (half(6.283185482025146484375) * _1004)), half(65504.0))) * _808) * (half4(frame.lightColor).xyz * _873), half3(float3(65504.0))), half(1.0)));
    return out;
}

