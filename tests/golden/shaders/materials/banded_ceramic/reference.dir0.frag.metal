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
    float3 _476 = fast::normalize(in.v_normal);
    float3 _483 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _568 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _617 = _476.y;
    float _622 = _476.z;
    float _627 = _476.x;
    float _793 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _568), 0.0, 1.0);
    float3 _801 = float3((0.1599999964237213134765625 * _793) * _793);
    float _810 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _568), 0.08900000154972076416015625, 1.0);
    float4 _817 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_476, _483), 9.9999997473787516355514526367188e-05), _810), level(0.0));
    float3 _857 = fma(fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_568)), float3(0.0), float3(1.0)) * 1.0, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _617)) + (frame.sh[2].xyz * _622)) + (frame.sh[3].xyz * _627)) + (((((frame.sh[4].xyz * (_627 * _617)) + (frame.sh[5].xyz * (_617 * _622))) + (frame.sh[6].xyz * fma(3.0 * _622, _622, -1.0))) + (frame.sh[7].xyz * (_627 * _622))) + (frame.sh[8].xyz * fma(_627, _627, -(_617 * _617)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_483, _476), level(_810 * (4.0 * (2.0 - _810)))).xyz * (mix(_817.xxx, _817.yyy, _801) * (float3(1.0) + (_801 * ((1.0 / _817.y) - 1.0)))));
    out.fragColor = float4(_857, 1.0);
    return out;
}

