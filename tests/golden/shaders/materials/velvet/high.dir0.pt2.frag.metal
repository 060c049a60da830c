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
    half3 _673 = normalize(half3(in.v_normal));
    float3 _679 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _815 = _673.y;
    half _820 = _673.z;
    half _825 = _673.x;
    half3 _893 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _815)) + (half4(frame.sh[2]).xyz * _820)) + (half4(frame.sh[3]).xyz * _825)) + (((((half4(frame.sh[4]).xyz * (_825 * _815)) + (half4(frame.sh[5]).xyz * (_815 * _820))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _820, _820, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_825 * _820))) + (half4(frame.sh[8]).xyz * fma(_825, _825, half(-float(_815 * _815))))), half3(float3(0.0)));
    half _934 = max(dot(_673, half3(_679)), half(9.9999997473787516355514526367188e-05));
    float4 _939 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_934, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _993 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1647 = half4(_939);
    half _952 = _1647.z;
    half _954 = fma(half(-float(max(_993.x, max(_993.y, _993.z)))), _952, half(1.0));
    half4 _1651 = half4(_939);
    half _959 = _1651.w;
    float4 _1009 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_679), _673)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1046 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1049 = dot(_1046, _1046);
    float3 _1054 = _1046 * rsqrt(fast::max(_1049, 9.9999999392252902907785028219223e-09));
    float _1058 = _1049 * float(frame.punctualLights[0].positionFalloff.w);
    float _1063 = fast::clamp(fma(-_1058, _1058, 1.0), 0.0, 1.0);
    float _1082 = fast::clamp(fma(dot(-_1054, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1116 = dot(_673, half3(_1054));
    half _1118 = clamp(_1116, half(0.0), half(1.0));
    half _1130 = clamp(dot(_673, half3(fast::normalize(_679 + _1054))), half(0.0), half(1.0));
    half _1201 = half(8192.0) * fma(half(-float(_1118)), _934, _1118 + _934);
    half _1205 = half(1.0) / (half(params.facet_alpha) * _1201);
    half _1212 = half(2048.0) * half(params.facet_alpha);
    half3 _1163 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1116 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1118), half3(float3(0.0)), half3(float3(1.0)))) * _954) + (_993 * ((((fma(_1205, _1201, half(2.0)) * pow(max(fma(half(-float(_1130)), _1130, half(1.0)), half(0.0)), half(0.5) * (_1205 * _1201))) * half(0.15915493667125701904296875)) * (_1118 * (_1205 * _1212))) * _959))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1063) * half(_1063)) / fast::max(_1049, 9.9999997473787516355514526367188e-05)) * half(_1082)) * half(_1082)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1276 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1279 = dot(_1276, _1276);
    float3 _1284 = _1276 * rsqrt(fast::max(_1279, 9.9999999392252902907785028219223e-09));
    float _1288 = _1279 * float(frame.punctualLights[1].positionFalloff.w);
    float _1293 = fast::clamp(fma(-_1288, _1288, 1.0), 0.0, 1.0);
    float _1312 = fast::clamp(fma(dot(-_1284, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1346 = dot(_673, half3(_1284));
    half _1348 = clamp(_1346, half(0.0), half(1.0));
    half _1360 = clamp(dot(_673, half3(fast::normalize(_679 + _1284))), half(0.0), half(1.0));
    half _1431 = half(8192.0) * fma(half(-float(_1348)), _934, _1348 + _934);
    half _1435 = half(1.0) / (half(params.facet_alpha) * _1431);
    half3 _1393 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1346 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1348), half3(float3(0.0)), half3(float3(1.0)))) * _954) + (_993 * ((((fma(_1435, _1431, half(2.0)) * pow(max(fma(half(-float(_1360)), _1360, half(1.0)), half(0.0)), half(0.5) * (_1435 * _1431))) * half(0.15915493667125701904296875)) * (_1348 * (_1435 * _1212))) * _959))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1293) * half(_1293)) / fast::max(_1279, 9.9999997473787516355514526367188e-05)) * half(_1312)) * half(_1312)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1009).xyz, _993 * _952, (half3(float3(params.facet_diffuseColor)) * _893) * _954) + _1163) + _1393, half(1.0)));
    return out;
}

