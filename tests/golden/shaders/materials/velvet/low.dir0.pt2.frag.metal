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
    half3 _480 = normalize(half3(in.v_normal));
    float3 _496 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _641 = max(dot(_480, half3(_496)), half(9.9999997473787516355514526367188e-05));
    float4 _646 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_641, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _692 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1245 = half4(_646);
    half _659 = _1245.z;
    half4 _1249 = half4(_646);
    half _663 = _1249.w;
    float4 _699 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_496), _480)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _736 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _739 = dot(_736, _736);
    float3 _744 = _736 * rsqrt(fast::max(_739, 9.9999999392252902907785028219223e-09));
    float _748 = _739 * float(frame.punctualLights[0].positionFalloff.w);
    float _753 = fast::clamp(fma(-_748, _748, 1.0), 0.0, 1.0);
    float _772 = fast::clamp(fma(dot(-_744, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _809 = clamp(dot(_480, half3(_744)), half(0.0), half(1.0));
    half _823 = clamp(dot(_480, normalize(half3(_496) + half3(_744))), half(0.0), half(1.0));
    half _881 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _884 = half(0.5) / half(params.facet_alpha);
    float3 _940 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _943 = dot(_940, _940);
    float3 _948 = _940 * rsqrt(fast::max(_943, 9.9999999392252902907785028219223e-09));
    float _952 = _943 * float(frame.punctualLights[1].positionFalloff.w);
    float _957 = fast::clamp(fma(-_952, _952, 1.0), 0.0, 1.0);
    float _976 = fast::clamp(fma(dot(-_948, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1013 = clamp(dot(_480, half3(_948)), half(0.0), half(1.0));
    half _1027 = clamp(dot(_480, normalize(half3(_496) + half3(_948))), half(0.0), half(1.0));
    half3 _1108 = (fma(half4(_699).xyz, _692 * _659, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_692.x, max(_692.y, _692.z)))), _659, half(1.0))) + min((_692 * ((((_881 * pow(max(fma(half(-float(_823)), _823, half(1.0)), half(0.0)), _884)) * half(0.15915493667125701904296875)) * (_809 / (half(4.0) * fma(half(-float(_809)), _641, _809 + _641)))) * _663)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_753) * half(_753)) / fast::max(_739, 9.9999997473787516355514526367188e-05)) * half(_772)) * half(_772)), float3(65504.0))), half3(float3(65504.0)))) + min((_692 * ((((_881 * pow(max(fma(half(-float(_1027)), _1027, half(1.0)), half(0.0)), _884)) * half(0.15915493667125701904296875)) * (_1013 / (half(4.0) * fma(half(-float(_1013)), _641, _1013 + _641)))) * _663)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_957) * half(_957)) / fast::max(_943, 9.9999997473787516355514526367188e-05)) * half(_976)) * half(_976)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1108, half(1.0)));
    return out;
}

