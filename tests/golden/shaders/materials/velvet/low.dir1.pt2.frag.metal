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
    half _802 = max(dot(_586, half3(_592)), half(9.9999997473787516355514526367188e-05));
    float4 _807 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_802, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1635 = half4(_807);
    half _820 = _1635.z;
    half _822 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _820, half(1.0));
    half4 _1639 = half4(_807);
    half _827 = _1639.w;
    float4 _836 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_592), _586)), level(params.facet_sheenLod));
    half3 _624 = half4(frame.lightDirection).xyz;
    half _892 = dot(_586, _624);
    half _894 = clamp(_892, half(0.0), half(1.0));
    half _906 = clamp(dot(_586, normalize(half3(_592) + _624)), half(0.0), half(1.0));
    half _975 = half(8192.0) * fma(half(-float(_894)), _802, _894 + _802);
    half _979 = half(1.0) / (half(params.facet_alpha) * _975);
    half _986 = half(2048.0) * half(params.facet_alpha);
    float3 _1050 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1053 = dot(_1050, _1050);
    float3 _1058 = _1050 * rsqrt(fast::max(_1053, 9.9999999392252902907785028219223e-09));
    float _1062 = _1053 * float(frame.punctualLights[0].positionFalloff.w);
    float _1067 = fast::clamp(fma(-_1062, _1062, 1.0), 0.0, 1.0);
    float _1086 = fast::clamp(fma(dot(-_1058, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1120 = dot(_586, half3(_1058));
    half _1122 = clamp(_1120, half(0.0), half(1.0));
    half _1134 = clamp(dot(_586, normalize(half3(_592) + half3(_1058))), half(0.0), half(1.0));
    half _1203 = half(8192.0) * fma(half(-float(_1122)), _802, _1122 + _802);
    half _1207 = half(1.0) / (half(params.facet_alpha) * _1203);
    half3 _1167 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1120 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1122), half3(float3(0.0)), half3(float3(1.0)))) * _822) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1207, _1203, half(2.0)) * pow(max(fma(half(-float(_1134)), _1134, half(1.0)), half(0.0)), half(0.5) * (_1207 * _1203))) * half(0.15915493667125701904296875)) * (_1122 * (_1207 * _986))) * _827))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1067) * half(_1067)) / fast::max(_1053, 9.9999997473787516355514526367188e-05)) * half(_1086)) * half(_1086)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1242 = (fma(half4(_836).xyz, half3(float3(params.facet_sheenColor)) * _820, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _586.y)) + (half4(frame.sh[2]).xyz * _586.z)) + (half4(frame.sh[3]).xyz * _586.x), half3(float3(0.0)))) * _822) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_892 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_894), half3(float3(0.0)), half3(float3(1.0)))) * _822) + (half3(float3(params.facet_sheenColor)) * ((((fma(_979, _975, half(2.0)) * pow(max(fma(half(-float(_906)), _906, half(1.0)), half(0.0)), half(0.5) * (_979 * _975))) * half(0.15915493667125701904296875)) * (_894 * (_979 * _986))) * _827))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1167;
    float3 _1278 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1281 = dot(_1278, _1278);
    float3 _1286 = _1278 * rsqrt(fast::max(_1281, 9.9999999392252902907785028219223e-09));
    float _1290 = _1281 * float(frame.punctualLights[1].positionFalloff.w);
    float _1295 = fast::clamp(fma(-_1290, _1290, 1.0), 0.0, 1.0);
    float _1314 = fast::clamp(fma(dot(-_1286, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1348 = dot(_586, half3(_1286));
    half _1350 = clamp(_1348, half(0.0), half(1.0));
    half _1362 = clamp(dot(_586, normalize(half3(_592) + half3(_1286))), half(0.0), half(1.0));
    half _1431 = half(8192.0) * fma(half(-float(_1350)), _802, _1350 + _802);
    half _1435 = half(1.0) / (half(params.facet_alpha) * _1431);
    half3 _1395 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1348 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1350), half3(float3(0.0)), half3(float3(1.0)))) * _822) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1435, _1431, half(2.0)) * pow(max(fma(half(-float(_1362)), _1362, half(1.0)), half(0.0)), half(0.5) * (_1435 * _1431))) * half(0.15915493667125701904296875)) * (_1350 * (_1435 * _986))) * _827))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1295) * half(_1295)) / fast::max(_1281, 9.9999997473787516355514526367188e-05)) * half(_1314)) * half(_1314)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1470 = _1242 + _1395;
    out.fragColor = float4(half4(_1470, half(1.0)));
    return out;
}

