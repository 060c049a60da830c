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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _566 = normalize(half3(in.v_normal));
    float3 _583 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _689 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float4 _715 = facet_irradiance.sample(facet_irradianceSmplr, float3(_566), level(0.0));
    half3 _739 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_689))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _806 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _689)), half(0.0), half(1.0));
    half3 _814 = half3((half(0.1599999964237213134765625) * _806) * _806);
    half _823 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _689)), half(0.08900000154972076416015625), half(1.0));
    half _772 = max(dot(_566, half3(_583)), half(9.9999997473787516355514526367188e-05));
    float4 _830 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_772, _823)), level(0.0));
    float4 _849 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_583), _566)), level(_823 * (half(4.0) * (half(2.0) - _823))));
    half3 _617 = half4(frame.lightDirection).xyz;
    half _985 = _823 * _823;
    half3 _996 = normalize(half3(_583) + _617);
    half _909 = clamp(dot(_566, _617), half(0.0), half(1.0));
    half4 _1065 = half4(cross(_566, _996), _985 * clamp(dot(_566, _996), half(0.0), half(1.0))) * half(64.0);
    half _1042 = half(6.283185482025146484375) * max(mix((half(2.0) * _909) * _772, _909 + _772, _985), half(0.000244140625));
    half _1044 = (half(4096.0) * _985) / (dot(_1065, _1065) * _1042);
    out.fragColor = float4(half4(fma(_739, half4(_715).xyz, half4(_849).xyz * mix(half4(_830).xxx, half4(_830).yyy, _814)) + min(((_739 * half(0.3183098733425140380859375)) + (_814 * min(_1044 * (_1044 * _1042), half(65504.0)))) * (half4(frame.lightColor).xyz * _909), half3(float3(65504.0))), half(1.0)));
    return out;
}

