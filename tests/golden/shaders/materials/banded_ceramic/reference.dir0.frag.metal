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
    float3 _470 = fast::normalize(in.v_normal);
    float3 _477 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _562 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _611 = _470.y;
    float _616 = _470.z;
    float _621 = _470.x;
    float _787 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _562), 0.0, 1.0);
    float3 _795 = float3((0.1599999964237213134765625 * _787) * _787);
    float _804 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _562), 0.08900000154972076416015625, 1.0);
    float4 _811 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_470, _477), 9.9999997473787516355514526367188e-05), _804), level(0.0));
    float3 _846 = fma(fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_562)), float3(0.0), float3(1.0)) * 1.0, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _611)) + (frame.sh[2].xyz * _616)) + (frame.sh[3].xyz * _621)) + (((((frame.sh[4].xyz * (_621 * _611)) + (frame.sh[5].xyz * (_611 * _616))) + (frame.sh[6].xyz * fma(3.0 * _616, _616, -1.0))) + (frame.sh[7].xyz * (_621 * _616))) + (frame.sh[8].xyz * fma(_621, _621, -(_611 * _611)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_477, _470), level(_804 * 4.0)).xyz * (mix(_811.xxx, _811.yyy, _795) * (float3(1.0) + (_795 * ((1.0 / _811.y) - 1.0)))));
    out.fragColor = float4(_846, 1.0);
    return out;
}

