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
    half3 _502 = normalize(half3(in.v_normal));
    float3 _518 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _661 = max(dot(_502, half3(_518)), half(9.9999997473787516355514526367188e-05));
    float4 _666 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_661, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _720 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1260 = half4(_666);
    half _679 = _1260.z;
    half4 _1264 = half4(_666);
    half _686 = _1264.w;
    float4 _736 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_518), _502)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _773 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _776 = dot(_773, _773);
    float3 _781 = _773 * rsqrt(fast::max(_776, 9.9999999392252902907785028219223e-09));
    float _785 = _776 * float(frame.punctualLights[0].positionFalloff.w);
    float _790 = fast::clamp(fma(-_785, _785, 1.0), 0.0, 1.0);
    float _809 = fast::clamp(fma(dot(-_781, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _842 = clamp(dot(_502, half3(_781)), half(0.0), half(1.0));
    half _854 = clamp(dot(_502, normalize(half3(_518) + half3(_781))), half(0.0), half(1.0));
    half _899 = half(8192.0) * fma(half(-float(_842)), _661, _842 + _661);
    half _903 = half(1.0) / (half(params.facet_alpha) * _899);
    half _910 = half(2048.0) * half(params.facet_alpha);
    float3 _968 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _971 = dot(_968, _968);
    float3 _976 = _968 * rsqrt(fast::max(_971, 9.9999999392252902907785028219223e-09));
    float _980 = _971 * float(frame.punctualLights[1].positionFalloff.w);
    float _985 = fast::clamp(fma(-_980, _980, 1.0), 0.0, 1.0);
    float _1004 = fast::clamp(fma(dot(-_976, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1037 = clamp(dot(_502, half3(_976)), half(0.0), half(1.0));
    half _1049 = clamp(dot(_502, normalize(half3(_518) + half3(_976))), half(0.0), half(1.0));
    half _1094 = half(8192.0) * fma(half(-float(_1037)), _661, _1037 + _661);
    half _1098 = half(1.0) / (half(params.facet_alpha) * _1094);
    half3 _1127 = (fma(half4(_736).xyz, _720 * _679, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_720.x, max(_720.y, _720.z)))), _679, half(1.0))) + min((_720 * ((((fma(_903, _899, half(2.0)) * pow(max(fma(half(-float(_854)), _854, half(1.0)), half(0.0)), half(0.5) * (_903 * _899))) * half(0.15915493667125701904296875)) * (_842 * (_903 * _910))) * _686)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_790) * half(_790)) / fast::max(_776, 9.9999997473787516355514526367188e-05)) * half(_809)) * half(_809)), float3(65504.0))), half3(float3(65504.0)))) + min((_720 * ((((fma(_1098, _1094, half(2.0)) * pow(max(fma(half(-float(_1049)), _1049, half(1.0)), half(0.0)), half(0.5) * (_1098 * _1094))) * half(0.15915493667125701904296875)) * (_1037 * (_1098 * _910))) * _686)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_985) * half(_985)) / fast::max(_971, 9.9999997473787516355514526367188e-05)) * half(_1004)) * half(_1004)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1127, half(1.0)));
    return out;
}

