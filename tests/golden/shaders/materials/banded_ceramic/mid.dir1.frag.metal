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
    half3 _527 = normalize(half3(in.v_normal));
    float3 _544 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _653 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _753 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _653)), half(0.0), half(1.0));
    half3 _761 = half3((half(0.1599999964237213134765625) * _753) * _753);
    half _770 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _653)), half(0.08900000154972076416015625), half(1.0));
    half _719 = max(dot(_527, half3(_544)), half(9.9999997473787516355514526367188e-05));
    float4 _777 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_719, _770)), level(0.0));
    float4 _796 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_544), _527)), level(_770 * (half(4.0) * (half(2.0) - _770))));
    half3 _581 = half4(frame.lightDirection).xyz;
    half _924 = _770 * _770;
    half3 _935 = normalize(half3(_544) + _581);
    half _854 = clamp(dot(_527, _581), half(0.0), half(1.0));
    half4 _1004 = half4(cross(_527, _935), _924 * clamp(dot(_527, _935), half(0.0), half(1.0))) * half(64.0);
    half _981 = half(6.283185482025146484375) * max(mix((half(2.0) * _854) * _719, _854 + _719, _924), half(0.000244140625));
    half _983 = (half(4096.0) * _924) / (dot(_1004, _1004) * _981);
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_653))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_796).xyz * mix(half4(_777).xxx, half4(_777).yyy, _761)) + min((_761 * min(_983 * (_983 * _981), half(65504.0))) * (half4(frame.lightColor).xyz * _854), half3(float3(65504.0))), half(1.0)));
    return out;
}

