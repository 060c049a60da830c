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
    half3 _779 = normalize(half3(in.v_normal));
    float3 _785 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _919 = _779.y;
    half _924 = _779.z;
    half _929 = _779.x;
    half3 _997 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _919)) + (half4(frame.sh[2]).xyz * _924)) + (half4(frame.sh[3]).xyz * _929)) + (((((half4(frame.sh[4]).xyz * (_929 * _919)) + (half4(frame.sh[5]).xyz * (_919 * _924))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _924, _924, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_929 * _924))) + (half4(frame.sh[8]).xyz * fma(_929, _929, half(-float(_919 * _919))))), half3(float3(0.0)));
    half _1047 = max(dot(_779, half3(_785)), half(9.9999997473787516355514526367188e-05));
    float4 _1086 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1047, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1105 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1086).y) - half(1.0)));
    float4 _1112 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_785), _779)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1157 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1160 = dot(_1157, _1157);
    float3 _1165 = _1157 * rsqrt(fast::max(_1160, 9.9999999392252902907785028219223e-09));
    float _1169 = _1160 * float(frame.punctualLights[0].positionFalloff.w);
    float _1174 = fast::clamp(fma(-_1169, _1169, 1.0), 0.0, 1.0);
    float _1193 = fast::clamp(fma(dot(-_1165, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1312 = fast::normalize(_785 + _1165);
    half _1256 = clamp(dot(_779, half3(_1165)), half(0.0), half(1.0));
    half _1352 = half(4096.0) * half(params.facet_alpha);
    half4 _1377 = half4(cross(_779, half3(_1312)), half(params.facet_alpha) * clamp(dot(_779, half3(_1312)), half(0.0), half(1.0))) * half(64.0);
    half _1358 = _1352 / dot(_1377, _1377);
    half _1388 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1394 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1398 = sqrt(fma(_1047 * _1047, _1394, _1388));
    half _1422 = half(1.0) - clamp(dot(half3(_1165), half3(_1312)), half(0.0), half(1.0));
    half _1425 = _1422 * _1422;
    half3 _1433 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1287 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1483 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1486 = dot(_1483, _1483);
    float3 _1491 = _1483 * rsqrt(fast::max(_1486, 9.9999999392252902907785028219223e-09));
    float _1495 = _1486 * float(frame.punctualLights[1].positionFalloff.w);
    float _1500 = fast::clamp(fma(-_1495, _1495, 1.0), 0.0, 1.0);
    float _1519 = fast::clamp(fma(dot(-_1491, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1638 = fast::normalize(_785 + _1491);
    half _1582 = clamp(dot(_779, half3(_1491)), half(0.0), half(1.0));
    half4 _1703 = half4(cross(_779, half3(_1638)), half(params.facet_alpha) * clamp(dot(_779, half3(_1638)), half(0.0), half(1.0))) * half(64.0);
    half _1684 = _1352 / dot(_1703, _1703);
    half _1748 = half(1.0) - clamp(dot(half3(_1491), half3(_1638)), half(0.0), half(1.0));
    half _1751 = _1748 * _1748;
    half3 _1773 = (fma(half3(float3(params.facet_diffuseColor)), _997, half4(_1112).xyz * (mix(half4(_1086).xxx, half4(_1086).yyy, half3(float3(params.facet_f0))) * _1105)) + min(fma((half3(float3(params.facet_f0)) + (_1433 * ((_1425 * _1425) * _1422))) * min(min((_1358 * _1358) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1256, _1398, _1047 * sqrt(fma(_1256 * _1256, _1394, _1388))), half(65504.0)), half(65504.0)), _1105, _1287) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1174) * half(_1174)) / fast::max(_1160, 9.9999997473787516355514526367188e-05)) * half(_1193)) * half(_1193)), float3(65504.0))) * _1256), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1433 * ((_1751 * _1751) * _1748))) * min(min((_1684 * _1684) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1582, _1398, _1047 * sqrt(fma(_1582 * _1582, _1394, _1388))), half(65504.0)), half(65504.0)), _1105, _1287) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1500) * half(_1500)) / fast::max(_1486, 9.9999997473787516355514526367188e-05)) * half(_1519)) * half(_1519)), float3(65504.0))) * _1582), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1773, half(1.0)));
    return out;
}

