#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _551 = normalize(half3(in.v_normal));
    float3 _567 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _770 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_551, half3(_567)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _749 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_567), _551)), level(params.facet_environmentLod));
    half3 _604 = half4(frame.lightDirection).xyz;
    half3 _839 = half3(_567) + _604;
    half3 _849 = _839 * (half(64.0) * rsqrt(dot(_839, _839)));
    half _858 = clamp(dot(_604, _849) * half(0.015625), half(0.0), half(1.0));
    half _987 = max(_858 * _858, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1009 = half4(cross(_551, _849), half(params.facet_alpha) * clamp(dot(_551, _849), half(0.0), half(64.0)));
    half _1020 = half(params.facet_ggxAlphaScaled) / (dot(_1009, _1009) * _987);
    float3 _1067 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1070 = dot(_1067, _1067);
    float3 _1075 = _1067 * rsqrt(fast::max(_1070, 9.9999999392252902907785028219223e-09));
    float _1079 = _1070 * float(frame.punctualLights[0].positionFalloff.w);
    float _1084 = fast::clamp(fma(-_1079, _1079, 1.0), 0.0, 1.0);
    float _1103 = fast::clamp(fma(dot(-_1075, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1167 = half3(_567) + half3(_1075);
    half3 _1177 = _1167 * (half(64.0) * rsqrt(dot(_1167, _1167)));
    half _1186 = clamp(dot(half3(_1075), _1177) * half(0.015625), half(0.0), half(1.0));
    half _1315 = max(_1186 * _1186, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1337 = half4(cross(_551, _1177), half(params.facet_alpha) * clamp(dot(_551, _1177), half(0.0), half(64.0)));
    half _1348 = half(params.facet_ggxAlphaScaled) / (dot(_1337, _1337) * _1315);
    float3 _1395 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1398 = dot(_1395, _1395);
    float3 _1403 = _1395 * rsqrt(fast::max(_1398, 9.9999999392252902907785028219223e-09));
    float _1407 = _1398 * float(frame.punctualLights[1].positionFalloff.w);
    float _1412 = fast::clamp(fma(-_1407, _1407, 1.0), 0.0, 1.0);
    float _1431 = fast::clamp(fma(dot(-_1403, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1495 = half3(_567) + half3(_1403);
    half3 _1505 = _1495 * (half(64.0) * rsqrt(dot(_1495, _1495)));
    half _1514 = clamp(dot(half3(_1403), _1505) * half(0.015625), half(0.0), half(1.0));
    half _1643 = max(_1514 * _1514, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1665 = half4(cross(_551, _1505), half(params.facet_alpha) * clamp(dot(_551, _1505), half(0.0), half(64.0)));
    half _1676 = half(params.facet_ggxAlphaScaled) / (dot(_1665, _1665) * _1643);
    half3 _1687 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_749).xyz * mix(half4(_770).xxx, half4(_770).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * half4(frame.lightColor).xyz) * (min((_1020 * _1020) * _987, half(65504.0)) * clamp(dot(_551, _604), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1084) * half(_1084)) / fast::max(_1070, 9.9999997473787516355514526367188e-05)) * half(_1103)) * half(_1103)), float3(65504.0)))) * (min((_1348 * _1348) * _1315, half(65504.0)) * clamp(dot(_551, half3(_1075)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1412) * half(_1412)) / fast::max(_1398, 9.9999997473787516355514526367188e-05)) * half(_1431)) * half(_1431)), float3(65504.0)))) * (min((_1676 * _1676) * _1643, half(65504.0)) * clamp(dot(_551, half3(_1403)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1687, half(1.0)));
    return out;
}

