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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _486 = normalize(half3(in.v_normal));
    float3 _502 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _642 = max(dot(_486, half3(_502)), half(9.9999997473787516355514526367188e-05));
    float4 _647 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_642, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1231 = half4(_647);
    half _660 = _1231.z;
    half4 _1235 = half4(_647);
    half _667 = _1235.w;
    float4 _676 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_502), _486)), level(params.facet_sheenLod));
    float3 _746 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _749 = dot(_746, _746);
    float3 _754 = _746 * rsqrt(fast::max(_749, 9.9999999392252902907785028219223e-09));
    float _758 = _749 * float(frame.punctualLights[0].positionFalloff.w);
    float _763 = fast::clamp(fma(-_758, _758, 1.0), 0.0, 1.0);
    float _782 = fast::clamp(fma(dot(-_754, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _815 = clamp(dot(_486, half3(_754)), half(0.0), half(1.0));
    half _827 = clamp(dot(_486, normalize(half3(_502) + half3(_754))), half(0.0), half(1.0));
    half _872 = half(8192.0) * fma(half(-float(_815)), _642, _815 + _642);
    half _876 = half(1.0) / (half(params.facet_alpha) * _872);
    half _883 = half(2048.0) * half(params.facet_alpha);
    float3 _941 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _944 = dot(_941, _941);
    float3 _949 = _941 * rsqrt(fast::max(_944, 9.9999999392252902907785028219223e-09));
    float _953 = _944 * float(frame.punctualLights[1].positionFalloff.w);
    float _958 = fast::clamp(fma(-_953, _953, 1.0), 0.0, 1.0);
    float _977 = fast::clamp(fma(dot(-_949, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1010 = clamp(dot(_486, half3(_949)), half(0.0), half(1.0));
    half _1022 = clamp(dot(_486, normalize(half3(_502) + half3(_949))), half(0.0), half(1.0));
    half _1067 = half(8192.0) * fma(half(-float(_1010)), _642, _1010 + _642);
    half _1071 = half(1.0) / (half(params.facet_alpha) * _1067);
    half3 _1100 = (fma(half4(_676).xyz, half3(float3(params.facet_sheenColor)) * _660, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _660, half(1.0))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_876, _872, half(2.0)) * pow(max(fma(half(-float(_827)), _827, half(1.0)), half(0.0)), half(0.5) * (_876 * _872))) * half(0.15915493667125701904296875)) * (_815 * (_876 * _883))) * _667)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_763) * half(_763)) / fast::max(_749, 9.9999997473787516355514526367188e-05)) * half(_782)) * half(_782)), float3(65504.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_1071, _1067, half(2.0)) * pow(max(fma(half(-float(_1022)), _1022, half(1.0)), half(0.0)), half(0.5) * (_1071 * _1067))) * half(0.15915493667125701904296875)) * (_1010 * (_1071 * _883))) * _667)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_958) * half(_958)) / fast::max(_944, 9.9999997473787516355514526367188e-05)) * half(_977)) * half(_977)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1100, half(1.0)));
    return out;
}

