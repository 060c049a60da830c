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
    half3 _642 = normalize(half3(in.v_normal));
    float3 _648 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _805 = _642.y;
    half _810 = _642.z;
    half _815 = _642.x;
    half3 _883 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _805)) + (half4(frame.sh[2]).xyz * _810)) + (half4(frame.sh[3]).xyz * _815)) + (((((half4(frame.sh[4]).xyz * (_815 * _805)) + (half4(frame.sh[5]).xyz * (_805 * _810))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _810, _810, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_815 * _810))) + (half4(frame.sh[8]).xyz * fma(_815, _815, half(-float(_805 * _805))))), half3(float3(0.0)));
    half _923 = max(dot(_642, half3(_648)), half(9.9999997473787516355514526367188e-05));
    float4 _928 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_923, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _974 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1814 = half4(_928);
    half _941 = _1814.z;
    half _943 = fma(half(-float(max(_974.x, max(_974.y, _974.z)))), _941, half(1.0));
    half4 _1818 = half4(_928);
    half _945 = _1818.w;
    float4 _981 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_648), _642)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1008 = dot(_642, half3(frame.lightDirection.xyz));
    half _1010 = clamp(_1008, half(0.0), half(1.0));
    half _1024 = clamp(dot(_642, half3(fast::normalize(_648 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1097 = half(8192.0) * fma(half(-float(_1010)), _923, _1010 + _923);
    half _1101 = half(1.0) / (half(params.facet_alpha) * _1097);
    half _1108 = half(2048.0) * half(params.facet_alpha);
    float3 _1172 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1175 = dot(_1172, _1172);
    float3 _1180 = _1172 * rsqrt(fast::max(_1175, 9.9999999392252902907785028219223e-09));
    float _1184 = _1175 * float(frame.punctualLights[0].positionFalloff.w);
    float _1189 = fast::clamp(fma(-_1184, _1184, 1.0), 0.0, 1.0);
    float _1208 = fast::clamp(fma(dot(-_1180, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1246 = dot(_642, half3(_1180));
    half _1248 = clamp(_1246, half(0.0), half(1.0));
    half _1262 = clamp(dot(_642, half3(fast::normalize(_648 + _1180))), half(0.0), half(1.0));
    half _1335 = half(8192.0) * fma(half(-float(_1248)), _923, _1248 + _923);
    half _1339 = half(1.0) / (half(params.facet_alpha) * _1335);
    half3 _1301 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1246 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1248), half3(float3(0.0)), half3(float3(1.0)))) * _943) + (_974 * ((((fma(_1339, _1335, half(2.0)) * pow(max(fma(half(-float(_1262)), _1262, half(1.0)), half(0.0)), half(0.5) * (_1339 * _1335))) * half(0.15915493667125701904296875)) * (_1248 * (_1339 * _1108))) * _945))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1189) * half(_1189)) / fast::max(_1175, 9.9999997473787516355514526367188e-05)) * half(_1208)) * half(_1208)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1374 = (fma(half4(_981).xyz, _974 * _941, (half3(float3(params.facet_diffuseColor)) * _883) * _943) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1008 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1010), half3(float3(0.0)), half3(float3(1.0)))) * _943) + (_974 * ((((fma(_1101, _1097, half(2.0)) * pow(max(fma(half(-float(_1024)), _1024, half(1.0)), half(0.0)), half(0.5) * (_1101 * _1097))) * half(0.15915493667125701904296875)) * (_1010 * (_1101 * _1108))) * _945))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1301;
    float3 _1410 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1413 = dot(_1410, _1410);
    float3 _1418 = _1410 * rsqrt(fast::max(_1413, 9.9999999392252902907785028219223e-09));
    float _1422 = _1413 * float(frame.punctualLights[1].positionFalloff.w);
    float _1427 = fast::clamp(fma(-_1422, _1422, 1.0), 0.0, 1.0);
    float _1446 = fast::clamp(fma(dot(-_1418, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1484 = dot(_642, half3(_1418));
    half _1486 = clamp(_1484, half(0.0), half(1.0));
    half _1500 = clamp(dot(_642, half3(fast::normalize(_648 + _1418))), half(0.0), half(1.0));
    half _1573 = half(8192.0) * fma(half(-float(_1486)), _923, _1486 + _923);
    half _1577 = half(1.0) / (half(params.facet_alpha) * _1573);
    half3 _1539 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1484 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1486), half3(float3(0.0)), half3(float3(1.0)))) * _943) + (_974 * ((((fma(_1577, _1573, half(2.0)) * pow(max(fma(half(-float(_1500)), _1500, half(1.0)), half(0.0)), half(0.5) * (_1577 * _1573))) * half(0.15915493667125701904296875)) * (_1486 * (_1577 * _1108))) * _945))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1427) * half(_1427)) / fast::max(_1413, 9.9999997473787516355514526367188e-05)) * half(_1446)) * half(_1446)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1374 + _1539, half(1.0)));
    return out;
}

