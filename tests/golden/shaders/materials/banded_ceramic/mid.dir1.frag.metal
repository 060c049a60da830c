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
    half3 _597 = normalize(half3(in.v_normal));
    float3 _614 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _723 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _823 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _723)), half(0.0), half(1.0));
    half3 _831 = half3((half(0.1599999964237213134765625) * _823) * _823);
    half _840 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _723)), half(0.08900000154972076416015625), half(1.0));
    float4 _847 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_597, half3(_614)), half(9.9999997473787516355514526367188e-05)), _840)), level(0.0));
    float4 _866 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_614), _597)), level(_840 * (half(4.0) * (half(2.0) - _840))));
    half3 _651 = half4(frame.lightDirection).xyz;
    half _1017 = _840 * _840;
    half3 _927 = half3(_614) + _651;
    half3 _937 = _927 * (half(64.0) * rsqrt(dot(_927, _927)));
    half _946 = clamp(dot(_651, _937) * half(0.015625), half(0.0), half(1.0));
    half4 _1174 = half4(cross(_597, _937), _1017 * clamp(dot(_597, _937), half(0.0), half(64.0)));
    half _1195 = (half(12.56637096405029296875) * max(_946 * _946, half(0.1500000059604644775390625))) * fma(half(-0.3125), _1017, half(1.00820004940032958984375));
    half _1207 = _1017 / ((dot(_1174, _1174) * half(0.000244140625)) * _1195);
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_723))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_866).xyz * mix(half4(_847).xxx, half4(_847).yyy, _831)) + min((_831 * half4(frame.lightColor).xyz) * (min((_1207 * _1207) * _1195, half(65504.0)) * clamp(dot(_597, _651), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

