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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _470 = normalize(half3(in.v_normal));
    float3 _477 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _562 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _611 = _470.y;
    half _616 = _470.z;
    half _621 = _470.x;
    half3 _689 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _611)) + (half4(frame.sh[2]).xyz * _616)) + (half4(frame.sh[3]).xyz * _621)) + (((((half4(frame.sh[4]).xyz * (_621 * _611)) + (half4(frame.sh[5]).xyz * (_611 * _616))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _616, _616, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_621 * _616))) + (half4(frame.sh[8]).xyz * fma(_621, _621, half(-float(_611 * _611))))), half3(float3(0.0)));
    half _787 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _562)), half(0.0), half(1.0));
    half3 _795 = half3((half(0.1599999964237213134765625) * _787) * _787);
    half _804 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _562)), half(0.08900000154972076416015625), half(1.0));
    float4 _811 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_470, half3(_477)), half(9.9999997473787516355514526367188e-05)), _804)), level(0.0));
    float4 _837 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_477), _470)), level(_804 * half(4.0)));
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_562))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), _689, half4(_837).xyz * (mix(half4(_811).xxx, half4(_811).yyy, _795) * (half3(float3(1.0)) + (_795 * ((half(1.0) / half4(_811).y) - half(1.0)))))), half(1.0)));
    return out;
}

