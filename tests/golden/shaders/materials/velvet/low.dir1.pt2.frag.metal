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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _605 = normalize(half3(in.v_normal));
    float3 _611 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _823 = max(dot(_605, half3(_611)), half(9.9999997473787516355514526367188e-05));
    float4 _828 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_823, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _882 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1669 = half4(_828);
    half _841 = _1669.z;
    half _843 = fma(half(-float(max(_882.x, max(_882.y, _882.z)))), _841, half(1.0));
    half4 _1673 = half4(_828);
    half _848 = _1673.w;
    float4 _901 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_611), _605)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _643 = half4(frame.lightDirection).xyz;
    half _924 = dot(_605, _643);
    half _926 = clamp(_924, half(0.0), half(1.0));
    half _938 = clamp(dot(_605, normalize(half3(_611) + _643)), half(0.0), half(1.0));
    half _1007 = half(8192.0) * fma(half(-float(_926)), _823, _926 + _823);
    half _1011 = half(1.0) / (half(params.facet_alpha) * _1007);
    half _1018 = half(2048.0) * half(params.facet_alpha);
    float3 _1082 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1085 = dot(_1082, _1082);
    float3 _1090 = _1082 * rsqrt(fast::max(_1085, 9.9999999392252902907785028219223e-09));
    float _1094 = _1085 * float(frame.punctualLights[0].positionFalloff.w);
    float _1099 = fast::clamp(fma(-_1094, _1094, 1.0), 0.0, 1.0);
    float _1118 = fast::clamp(fma(dot(-_1090, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1152 = dot(_605, half3(_1090));
    half _1154 = clamp(_1152, half(0.0), half(1.0));
    half _1166 = clamp(dot(_605, normalize(half3(_611) + half3(_1090))), half(0.0), half(1.0));
    half _1235 = half(8192.0) * fma(half(-float(_1154)), _823, _1154 + _823);
    half _1239 = half(1.0) / (half(params.facet_alpha) * _1235);
    half3 _1199 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1152 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1154), half3(float3(0.0)), half3(float3(1.0)))) * _843) + (_882 * ((((fma(_1239, _1235, half(2.0)) * pow(max(fma(half(-float(_1166)), _1166, half(1.0)), half(0.0)), half(0.5) * (_1239 * _1235))) * half(0.15915493667125701904296875)) * (_1154 * (_1239 * _1018))) * _848))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1099) * half(_1099)) / fast::max(_1085, 9.9999997473787516355514526367188e-05)) * half(_1118)) * half(_1118)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1274 = (fma(half4(_901).xyz, _882 * _841, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _605.y)) + (half4(frame.sh[2]).xyz * _605.z)) + (half4(frame.sh[3]).xyz * _605.x), half3(float3(0.0)))) * _843) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_924 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_926), half3(float3(0.0)), half3(float3(1.0)))) * _843) + (_882 * ((((fma(_1011, _1007, half(2.0)) * pow(max(fma(half(-float(_938)), _938, half(1.0)), half(0.0)), half(0.5) * (_1011 * _1007))) * half(0.15915493667125701904296875)) * (_926 * (_1011 * _1018))) * _848))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1199;
    float3 _1310 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1313 = dot(_1310, _1310);
    float3 _1318 = _1310 * rsqrt(fast::max(_1313, 9.9999999392252902907785028219223e-09));
    float _1322 = _1313 * float(frame.punctualLights[1].positionFalloff.w);
    float _1327 = fast::clamp(fma(-_1322, _1322, 1.0), 0.0, 1.0);
    float _1346 = fast::clamp(fma(dot(-_1318, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1380 = dot(_605, half3(_1318));
    half _1382 = clamp(_1380, half(0.0), half(1.0));
    half _1394 = clamp(dot(_605, normalize(half3(_611) + half3(_1318))), half(0.0), half(1.0));
    half _1463 = half(8192.0) * fma(half(-float(_1382)), _823, _1382 + _823);
    half _1467 = half(1.0) / (half(params.facet_alpha) * _1463);
    half3 _1427 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1380 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1382), half3(float3(0.0)), half3(float3(1.0)))) * _843) + (_882 * ((((fma(_1467, _1463, half(2.0)) * pow(max(fma(half(-float(_1394)), _1394, half(1.0)), half(0.0)), half(0.5) * (_1467 * _1463))) * half(0.15915493667125701904296875)) * (_1382 * (_1467 * _1018))) * _848))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1327) * half(_1327)) / fast::max(_1313, 9.9999997473787516355514526367188e-05)) * half(_1346)) * half(_1346)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1502 = _1274 + _1427;
    out.fragColor = float4(half4(_1502, half(1.0)));
    return out;
}

