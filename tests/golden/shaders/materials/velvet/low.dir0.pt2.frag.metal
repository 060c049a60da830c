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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _586 = normalize(half3(in.v_normal));
    float3 _592 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _781 = max(dot(_586, half3(_592)), half(9.9999997473787516355514526367188e-05));
    float4 _786 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_781, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1451 = half4(_786);
    half _799 = _1451.z;
    half _801 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _799, half(1.0));
    half4 _1455 = half4(_786);
    half _806 = _1455.w;
    float4 _815 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_592), _586)), level(params.facet_sheenLod));
    float3 _885 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _888 = dot(_885, _885);
    float3 _893 = _885 * rsqrt(fast::max(_888, 9.9999999392252902907785028219223e-09));
    float _897 = _888 * float(frame.punctualLights[0].positionFalloff.w);
    float _902 = fast::clamp(fma(-_897, _897, 1.0), 0.0, 1.0);
    float _921 = fast::clamp(fma(dot(-_893, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _955 = dot(_586, half3(_893));
    half _957 = clamp(_955, half(0.0), half(1.0));
    half _969 = clamp(dot(_586, normalize(half3(_592) + half3(_893))), half(0.0), half(1.0));
    half _1038 = half(8192.0) * fma(half(-float(_957)), _781, _957 + _781);
    half _1042 = half(1.0) / (half(params.facet_alpha) * _1038);
    half _1049 = half(2048.0) * half(params.facet_alpha);
    half3 _1002 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_955 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_957), half3(float3(0.0)), half3(float3(1.0)))) * _801) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1042, _1038, half(2.0)) * pow(max(fma(half(-float(_969)), _969, half(1.0)), half(0.0)), half(0.5) * (_1042 * _1038))) * half(0.15915493667125701904296875)) * (_957 * (_1042 * _1049))) * _806))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_902) * half(_902)) / fast::max(_888, 9.9999997473787516355514526367188e-05)) * half(_921)) * half(_921)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1113 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1116 = dot(_1113, _1113);
    float3 _1121 = _1113 * rsqrt(fast::max(_1116, 9.9999999392252902907785028219223e-09));
    float _1125 = _1116 * float(frame.punctualLights[1].positionFalloff.w);
    float _1130 = fast::clamp(fma(-_1125, _1125, 1.0), 0.0, 1.0);
    float _1149 = fast::clamp(fma(dot(-_1121, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1183 = dot(_586, half3(_1121));
    half _1185 = clamp(_1183, half(0.0), half(1.0));
    half _1197 = clamp(dot(_586, normalize(half3(_592) + half3(_1121))), half(0.0), half(1.0));
    half _1266 = half(8192.0) * fma(half(-float(_1185)), _781, _1185 + _781);
    half _1270 = half(1.0) / (half(params.facet_alpha) * _1266);
    half3 _1230 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1183 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1185), half3(float3(0.0)), half3(float3(1.0)))) * _801) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1270, _1266, half(2.0)) * pow(max(fma(half(-float(_1197)), _1197, half(1.0)), half(0.0)), half(0.5) * (_1270 * _1266))) * half(0.15915493667125701904296875)) * (_1185 * (_1270 * _1049))) * _806))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1130) * half(_1130)) / fast::max(_1116, 9.9999997473787516355514526367188e-05)) * half(_1149)) * half(_1149)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1305 = (fma(half4(_815).xyz, half3(float3(params.facet_sheenColor)) * _799, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _586.y)) + (half4(frame.sh[2]).xyz * _586.z)) + (half4(frame.sh[3]).xyz * _586.x), half3(float3(0.0)))) * _801) + _1002) + _1230;
    out.fragColor = float4(half4(_1305, half(1.0)));
    return out;
}

