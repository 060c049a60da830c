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
    half _635 = max(dot(_456, half3(_472)), half(9.9999997473787516355514526367188e-05));
    float4 _640 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_635, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1340 = half4(_640);
    half _643 = _1340.w;
    float4 _668 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_472), _456)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _676 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half3 _509 = half4(frame.lightDirection).xyz;
    half _716 = clamp(dot(_456, _509), half(0.0), half(1.0));
    half _720 = clamp(dot(_456, normalize(half3(_472) + _509)), half(0.0), half(1.0));
    half _778 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _781 = half(0.5) / half(params.facet_alpha);
    float3 _837 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _840 = dot(_837, _837);
    float3 _845 = _837 * rsqrt(fast::max(_840, 9.9999999392252902907785028219223e-09));
    float _849 = _840 * float(frame.punctualLights[0].positionFalloff.w);
    float _854 = fast::clamp(fma(-_849, _849, 1.0), 0.0, 1.0);
    float _873 = fast::clamp(fma(dot(-_845, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _920 = clamp(dot(_456, half3(_845)), half(0.0), half(1.0));
    half _924 = clamp(dot(_456, normalize(half3(_472) + half3(_845))), half(0.0), half(1.0));
    float3 _1041 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1044 = dot(_1041, _1041);
    float3 _1049 = _1041 * rsqrt(fast::max(_1044, 9.9999999392252902907785028219223e-09));
    float _1053 = _1044 * float(frame.punctualLights[1].positionFalloff.w);
    float _1058 = fast::clamp(fma(-_1053, _1053, 1.0), 0.0, 1.0);
    float _1077 = fast::clamp(fma(dot(-_1049, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1124 = clamp(dot(_456, half3(_1049)), half(0.0), half(1.0));
    half _1128 = clamp(dot(_456, normalize(half3(_472) + half3(_1049))), half(0.0), half(1.0));
    half3 _1209 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_668).xyz * (_676 * half4(_640).z)) + min((_676 * ((((_778 * pow(max(fma(half(-float(_720)), _720, half(1.0)), half(0.0)), _781)) * half(0.15915493667125701904296875)) * (_716 / (half(4.0) * fma(half(-float(_716)), _635, _716 + _635)))) * _643)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_676 * ((((_778 * pow(max(fma(half(-float(_924)), _924, half(1.0)), half(0.0)), _781)) * half(0.15915493667125701904296875)) * (_920 / (half(4.0) * fma(half(-float(_920)), _635, _920 + _635)))) * _643)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_854) * half(_854)) / fast::max(_840, 9.9999997473787516355514526367188e-05)) * half(_873)) * half(_873)), float3(65504.0))), half3(float3(65504.0)))) + min((_676 * ((((_778 * pow(max(fma(half(-float(_1128)), _1128, half(1.0)), half(0.0)), _781)) * half(0.15915493667125701904296875)) * (_1124 / (half(4.0) * fma(half(-float(_1124)), _635, _1124 + _635)))) * _643)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1058) * half(_1058)) / fast::max(_1044, 9.9999997473787516355514526367188e-05)) * half(_1077)) * half(_1077)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1209, half(1.0)));
    return out;
}

