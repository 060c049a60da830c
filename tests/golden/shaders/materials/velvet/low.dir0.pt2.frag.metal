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
    half3 _512 = normalize(half3(in.v_normal));
    float3 _528 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _673 = max(dot(_512, half3(_528)), half(9.9999997473787516355514526367188e-05));
    float4 _678 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_673, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _729 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1326 = half4(_678);
    half _691 = _1326.z;
    half4 _1330 = half4(_678);
    half _695 = _1330.w;
    float4 _736 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_528), _512)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _773 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _776 = dot(_773, _773);
    float3 _781 = _773 * rsqrt(fast::max(_776, 9.9999999392252902907785028219223e-09));
    float _785 = _776 * float(frame.punctualLights[0].positionFalloff.w);
    float _790 = fast::clamp(fma(-_785, _785, 1.0), 0.0, 1.0);
    float _809 = fast::clamp(fma(dot(-_781, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _877 = clamp(dot(_512, half3(_781)), half(0.0), half(1.0));
    half _881 = clamp(dot(_512, normalize(half3(_528) + half3(_781))), half(0.0), half(1.0));
    half _923 = half(8192.0) * fma(half(-float(_877)), _673, _877 + _673);
    half _927 = half(1.0) / (half(params.facet_alpha) * _923);
    half _934 = half(2048.0) * half(params.facet_alpha);
    float3 _999 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1002 = dot(_999, _999);
    float3 _1007 = _999 * rsqrt(fast::max(_1002, 9.9999999392252902907785028219223e-09));
    float _1011 = _1002 * float(frame.punctualLights[1].positionFalloff.w);
    float _1016 = fast::clamp(fma(-_1011, _1011, 1.0), 0.0, 1.0);
    float _1035 = fast::clamp(fma(dot(-_1007, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1103 = clamp(dot(_512, half3(_1007)), half(0.0), half(1.0));
    half _1107 = clamp(dot(_512, normalize(half3(_528) + half3(_1007))), half(0.0), half(1.0));
    half _1149 = half(8192.0) * fma(half(-float(_1103)), _673, _1103 + _673);
    half _1153 = half(1.0) / (half(params.facet_alpha) * _1149);
    half3 _1189 = (fma(half4(_736).xyz, _729 * _691, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_729.x, max(_729.y, _729.z)))), _691, half(1.0))) + min((_729 * ((((fma(_927, _923, half(2.0)) * pow(max(fma(half(-float(_881)), _881, half(1.0)), half(0.0)), half(0.5) * (_927 * _923))) * half(0.15915493667125701904296875)) * (_877 * (_927 * _934))) * _695)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_790) * half(_790)) / fast::max(_776, 9.9999997473787516355514526367188e-05)) * half(_809)) * half(_809)), float3(65504.0))), half3(float3(65504.0)))) + min((_729 * ((((fma(_1153, _1149, half(2.0)) * pow(max(fma(half(-float(_1107)), _1107, half(1.0)), half(0.0)), half(0.5) * (_1153 * _1149))) * half(0.15915493667125701904296875)) * (_1103 * (_1153 * _934))) * _695)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1016) * half(_1016)) / fast::max(_1002, 9.9999997473787516355514526367188e-05)) * half(_1035)) * half(_1035)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1189, half(1.0)));
    return out;
}

