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
    half3 _505 = normalize(half3(in.v_normal));
    float3 _521 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _664 = max(dot(_505, half3(_521)), half(9.9999997473787516355514526367188e-05));
    float4 _669 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_664, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _723 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1266 = half4(_669);
    half _682 = _1266.z;
    half4 _1270 = half4(_669);
    half _689 = _1270.w;
    float4 _742 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_521), _505)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _779 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _782 = dot(_779, _779);
    float3 _787 = _779 * rsqrt(fast::max(_782, 9.9999999392252902907785028219223e-09));
    float _791 = _782 * float(frame.punctualLights[0].positionFalloff.w);
    float _796 = fast::clamp(fma(-_791, _791, 1.0), 0.0, 1.0);
    float _815 = fast::clamp(fma(dot(-_787, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _848 = clamp(dot(_505, half3(_787)), half(0.0), half(1.0));
    half _860 = clamp(dot(_505, normalize(half3(_521) + half3(_787))), half(0.0), half(1.0));
    half _905 = half(8192.0) * fma(half(-float(_848)), _664, _848 + _664);
    half _909 = half(1.0) / (half(params.facet_alpha) * _905);
    half _916 = half(2048.0) * half(params.facet_alpha);
    float3 _974 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _977 = dot(_974, _974);
    float3 _982 = _974 * rsqrt(fast::max(_977, 9.9999999392252902907785028219223e-09));
    float _986 = _977 * float(frame.punctualLights[1].positionFalloff.w);
    float _991 = fast::clamp(fma(-_986, _986, 1.0), 0.0, 1.0);
    float _1010 = fast::clamp(fma(dot(-_982, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1043 = clamp(dot(_505, half3(_982)), half(0.0), half(1.0));
    half _1055 = clamp(dot(_505, normalize(half3(_521) + half3(_982))), half(0.0), half(1.0));
    half _1100 = half(8192.0) * fma(half(-float(_1043)), _664, _1043 + _664);
    half _1104 = half(1.0) / (half(params.facet_alpha) * _1100);
    half3 _1133 = (fma(half4(_742).xyz, _723 * _682, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_723.x, max(_723.y, _723.z)))), _682, half(1.0))) + min((_723 * ((((fma(_909, _905, half(2.0)) * pow(max(fma(half(-float(_860)), _860, half(1.0)), half(0.0)), half(0.5) * (_909 * _905))) * half(0.15915493667125701904296875)) * (_848 * (_909 * _916))) * _689)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_796) * half(_796)) / fast::max(_782, 9.9999997473787516355514526367188e-05)) * half(_815)) * half(_815)), float3(65504.0))), half3(float3(65504.0)))) + min((_723 * ((((fma(_1104, _1100, half(2.0)) * pow(max(fma(half(-float(_1055)), _1055, half(1.0)), half(0.0)), half(0.5) * (_1104 * _1100))) * half(0.15915493667125701904296875)) * (_1043 * (_1104 * _916))) * _689)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_991) * half(_991)) / fast::max(_977, 9.9999997473787516355514526367188e-05)) * half(_1010)) * half(_1010)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1133, half(1.0)));
    return out;
}

