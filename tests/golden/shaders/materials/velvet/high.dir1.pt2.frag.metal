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
    half3 _650 = normalize(half3(in.v_normal));
    float3 _656 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _813 = _650.y;
    half _818 = _650.z;
    half _823 = _650.x;
    half3 _891 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _813)) + (half4(frame.sh[2]).xyz * _818)) + (half4(frame.sh[3]).xyz * _823)) + (((((half4(frame.sh[4]).xyz * (_823 * _813)) + (half4(frame.sh[5]).xyz * (_813 * _818))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _818, _818, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_823 * _818))) + (half4(frame.sh[8]).xyz * fma(_823, _823, half(-float(_813 * _813))))), half3(float3(0.0)));
    half _931 = max(dot(_650, half3(_656)), half(9.9999997473787516355514526367188e-05));
    float4 _936 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_931, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _982 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1825 = half4(_936);
    half _949 = _1825.z;
    half _951 = fma(half(-float(max(_982.x, max(_982.y, _982.z)))), _949, half(1.0));
    half4 _1829 = half4(_936);
    half _953 = _1829.w;
    float4 _989 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_656), _650)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1016 = dot(_650, half3(frame.lightDirection.xyz));
    half _1018 = clamp(_1016, half(0.0), half(1.0));
    half _1032 = clamp(dot(_650, half3(fast::normalize(_656 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1116 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _1119 = half(0.5) / half(params.facet_alpha);
    float3 _1181 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1184 = dot(_1181, _1181);
    float3 _1189 = _1181 * rsqrt(fast::max(_1184, 9.9999999392252902907785028219223e-09));
    float _1193 = _1184 * float(frame.punctualLights[0].positionFalloff.w);
    float _1198 = fast::clamp(fma(-_1193, _1193, 1.0), 0.0, 1.0);
    float _1217 = fast::clamp(fma(dot(-_1189, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1255 = dot(_650, half3(_1189));
    half _1257 = clamp(_1255, half(0.0), half(1.0));
    half _1271 = clamp(dot(_650, half3(fast::normalize(_656 + _1189))), half(0.0), half(1.0));
    half3 _1310 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1255 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1257), half3(float3(0.0)), half3(float3(1.0)))) * _951) + (_982 * ((((_1116 * pow(max(fma(half(-float(_1271)), _1271, half(1.0)), half(0.0)), _1119)) * half(0.15915493667125701904296875)) * (_1257 / (half(4.0) * fma(half(-float(_1257)), _931, _1257 + _931)))) * _953))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1198) * half(_1198)) / fast::max(_1184, 9.9999997473787516355514526367188e-05)) * half(_1217)) * half(_1217)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1384 = (fma(half4(_989).xyz, _982 * _949, (half3(float3(params.facet_diffuseColor)) * _891) * _951) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1016 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1018), half3(float3(0.0)), half3(float3(1.0)))) * _951) + (_982 * ((((_1116 * pow(max(fma(half(-float(_1032)), _1032, half(1.0)), half(0.0)), _1119)) * half(0.15915493667125701904296875)) * (_1018 / (half(4.0) * fma(half(-float(_1018)), _931, _1018 + _931)))) * _953))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1310;
    float3 _1420 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1423 = dot(_1420, _1420);
    float3 _1428 = _1420 * rsqrt(fast::max(_1423, 9.9999999392252902907785028219223e-09));
    float _1432 = _1423 * float(frame.punctualLights[1].positionFalloff.w);
    float _1437 = fast::clamp(fma(-_1432, _1432, 1.0), 0.0, 1.0);
    float _1456 = fast::clamp(fma(dot(-_1428, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1494 = dot(_650, half3(_1428));
    half _1496 = clamp(_1494, half(0.0), half(1.0));
    half _1510 = clamp(dot(_650, half3(fast::normalize(_656 + _1428))), half(0.0), half(1.0));
    half3 _1549 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1494 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1496), half3(float3(0.0)), half3(float3(1.0)))) * _951) + (_982 * ((((_1116 * pow(max(fma(half(-float(_1510)), _1510, half(1.0)), half(0.0)), _1119)) * half(0.15915493667125701904296875)) * (_1496 / (half(4.0) * fma(half(-float(_1496)), _931, _1496 + _931)))) * _953))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1437) * half(_1437)) / fast::max(_1423, 9.9999997473787516355514526367188e-05)) * half(_1456)) * half(_1456)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1384 + _1549, half(1.0)));
    return out;
}

