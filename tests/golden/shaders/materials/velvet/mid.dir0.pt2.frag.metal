#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _456 = normalize(half3(in.v_normal));
    float3 _472 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _614 = max(dot(_456, half3(_472)), half(9.9999997473787516355514526367188e-05));
    float4 _619 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_614, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1195 = half4(_619);
    half _622 = _1195.w;
    float4 _647 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_472), _456)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _655 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    float3 _696 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _699 = dot(_696, _696);
    float3 _704 = _696 * rsqrt(fast::max(_699, 9.9999999392252902907785028219223e-09));
    float _708 = _699 * float(frame.punctualLights[0].positionFalloff.w);
    float _713 = fast::clamp(fma(-_708, _708, 1.0), 0.0, 1.0);
    float _732 = fast::clamp(fma(dot(-_704, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _779 = clamp(dot(_456, half3(_704)), half(0.0), half(1.0));
    half _783 = clamp(dot(_456, normalize(half3(_472) + half3(_704))), half(0.0), half(1.0));
    half _841 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _844 = half(0.5) / half(params.facet_alpha);
    float3 _900 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _903 = dot(_900, _900);
    float3 _908 = _900 * rsqrt(fast::max(_903, 9.9999999392252902907785028219223e-09));
    float _912 = _903 * float(frame.punctualLights[1].positionFalloff.w);
    float _917 = fast::clamp(fma(-_912, _912, 1.0), 0.0, 1.0);
    float _936 = fast::clamp(fma(dot(-_908, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _983 = clamp(dot(_456, half3(_908)), half(0.0), half(1.0));
    half _987 = clamp(dot(_456, normalize(half3(_472) + half3(_908))), half(0.0), half(1.0));
    half3 _1068 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_647).xyz * (_655 * half4(_619).z)) + min((_655 * ((((_841 * pow(max(fma(half(-float(_783)), _783, half(1.0)), half(0.0)), _844)) * half(0.15915493667125701904296875)) * (_779 / (half(4.0) * fma(half(-float(_779)), _614, _779 + _614)))) * _622)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_713) * half(_713)) / fast::max(_699, 9.9999997473787516355514526367188e-05)) * half(_732)) * half(_732)), float3(65504.0))), half3(float3(65504.0)))) + min((_655 * ((((_841 * pow(max(fma(half(-float(_987)), _987, half(1.0)), half(0.0)), _844)) * half(0.15915493667125701904296875)) * (_983 / (half(4.0) * fma(half(-float(_983)), _614, _983 + _614)))) * _622)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_917) * half(_917)) / fast::max(_903, 9.9999997473787516355514526367188e-05)) * half(_936)) * half(_936)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1068, half(1.0)));
    return out;
}

