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
    half3 _682 = normalize(half3(in.v_normal));
    float3 _688 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _845 = _682.y;
    half _850 = _682.z;
    half _855 = _682.x;
    half3 _923 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _845)) + (half4(frame.sh[2]).xyz * _850)) + (half4(frame.sh[3]).xyz * _855)) + (((((half4(frame.sh[4]).xyz * (_855 * _845)) + (half4(frame.sh[5]).xyz * (_845 * _850))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _850, _850, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_855 * _850))) + (half4(frame.sh[8]).xyz * fma(_855, _855, half(-float(_845 * _845))))), half3(float3(0.0)));
    half _963 = max(dot(_682, half3(_688)), half(9.9999997473787516355514526367188e-05));
    float4 _968 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_963, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1019 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1928 = half4(_968);
    half _981 = _1928.z;
    half _983 = fma(half(-float(max(_1019.x, max(_1019.y, _1019.z)))), _981, half(1.0));
    half4 _1932 = half4(_968);
    half _985 = _1932.w;
    float4 _1026 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_688), _682)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1044 = dot(_682, half3(frame.lightDirection.xyz));
    half _1046 = clamp(_1044, half(0.0), half(1.0));
    half _1114 = clamp(dot(_682, half3(fast::normalize(_688 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1158 = half(8192.0) * fma(half(-float(_1046)), _963, _1046 + _963);
    half _1162 = half(1.0) / (half(params.facet_alpha) * _1158);
    half _1169 = half(2048.0) * half(params.facet_alpha);
    float3 _1240 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1243 = dot(_1240, _1240);
    float3 _1248 = _1240 * rsqrt(fast::max(_1243, 9.9999999392252902907785028219223e-09));
    float _1252 = _1243 * float(frame.punctualLights[0].positionFalloff.w);
    float _1257 = fast::clamp(fma(-_1252, _1252, 1.0), 0.0, 1.0);
    float _1276 = fast::clamp(fma(dot(-_1248, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1305 = dot(_682, half3(_1248));
    half _1307 = clamp(_1305, half(0.0), half(1.0));
    half _1375 = clamp(dot(_682, half3(fast::normalize(_688 + _1248))), half(0.0), half(1.0));
    half _1419 = half(8192.0) * fma(half(-float(_1307)), _963, _1307 + _963);
    half _1423 = half(1.0) / (half(params.facet_alpha) * _1419);
    half3 _1341 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1305 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1307), half3(float3(0.0)), half3(float3(1.0)))) * _983) + (_1019 * ((((fma(_1423, _1419, half(2.0)) * pow(max(fma(half(-float(_1375)), _1375, half(1.0)), half(0.0)), half(0.5) * (_1423 * _1419))) * half(0.15915493667125701904296875)) * (_1307 * (_1423 * _1169))) * _985))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1257) * half(_1257)) / fast::max(_1243, 9.9999997473787516355514526367188e-05)) * half(_1276)) * half(_1276)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1465 = (fma(half4(_1026).xyz, _1019 * _981, (half3(float3(params.facet_diffuseColor)) * _923) * _983) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1044 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1046), half3(float3(0.0)), half3(float3(1.0)))) * _983) + (_1019 * ((((fma(_1162, _1158, half(2.0)) * pow(max(fma(half(-float(_1114)), _1114, half(1.0)), half(0.0)), half(0.5) * (_1162 * _1158))) * half(0.15915493667125701904296875)) * (_1046 * (_1162 * _1169))) * _985))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1341;
    float3 _1501 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1504 = dot(_1501, _1501);
    float3 _1509 = _1501 * rsqrt(fast::max(_1504, 9.9999999392252902907785028219223e-09));
    float _1513 = _1504 * float(frame.punctualLights[1].positionFalloff.w);
    float _1518 = fast::clamp(fma(-_1513, _1513, 1.0), 0.0, 1.0);
    float _1537 = fast::clamp(fma(dot(-_1509, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1566 = dot(_682, half3(_1509));
    half _1568 = clamp(_1566, half(0.0), half(1.0));
    half _1636 = clamp(dot(_682, half3(fast::normalize(_688 + _1509))), half(0.0), half(1.0));
    half _1680 = half(8192.0) * fma(half(-float(_1568)), _963, _1568 + _963);
    half _1684 = half(1.0) / (half(params.facet_alpha) * _1680);
    half3 _1602 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1566 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1568), half3(float3(0.0)), half3(float3(1.0)))) * _983) + (_1019 * ((((fma(_1684, _1680, half(2.0)) * pow(max(fma(half(-float(_1636)), _1636, half(1.0)), half(0.0)), half(0.5) * (_1684 * _1680))) * half(0.15915493667125701904296875)) * (_1568 * (_1684 * _1169))) * _985))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1518) * half(_1518)) / fast::max(_1504, 9.9999997473787516355514526367188e-05)) * half(_1537)) * half(_1537)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1465 + _1602, half(1.0)));
    return out;
}

