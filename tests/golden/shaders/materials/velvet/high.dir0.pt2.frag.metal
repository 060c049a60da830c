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
    half _792 = _650.y;
    half _797 = _650.z;
    half _802 = _650.x;
    half3 _870 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _792)) + (half4(frame.sh[2]).xyz * _797)) + (half4(frame.sh[3]).xyz * _802)) + (((((half4(frame.sh[4]).xyz * (_802 * _792)) + (half4(frame.sh[5]).xyz * (_792 * _797))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _797, _797, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_802 * _797))) + (half4(frame.sh[8]).xyz * fma(_802, _802, half(-float(_792 * _792))))), half3(float3(0.0)));
    half _910 = max(dot(_650, half3(_656)), half(9.9999997473787516355514526367188e-05));
    float4 _915 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_910, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _961 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1628 = half4(_915);
    half _928 = _1628.z;
    half _930 = fma(half(-float(max(_961.x, max(_961.y, _961.z)))), _928, half(1.0));
    half4 _1632 = half4(_915);
    half _932 = _1632.w;
    float4 _968 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_656), _650)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1005 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1008 = dot(_1005, _1005);
    float3 _1013 = _1005 * rsqrt(fast::max(_1008, 9.9999999392252902907785028219223e-09));
    float _1017 = _1008 * float(frame.punctualLights[0].positionFalloff.w);
    float _1022 = fast::clamp(fma(-_1017, _1017, 1.0), 0.0, 1.0);
    float _1041 = fast::clamp(fma(dot(-_1013, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1079 = dot(_650, half3(_1013));
    half _1081 = clamp(_1079, half(0.0), half(1.0));
    half _1095 = clamp(dot(_650, half3(fast::normalize(_656 + _1013))), half(0.0), half(1.0));
    half _1179 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _1182 = half(0.5) / half(params.facet_alpha);
    half3 _1134 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1079 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1081), half3(float3(0.0)), half3(float3(1.0)))) * _930) + (_961 * ((((_1179 * pow(max(fma(half(-float(_1095)), _1095, half(1.0)), half(0.0)), _1182)) * half(0.15915493667125701904296875)) * (_1081 / (half(4.0) * fma(half(-float(_1081)), _910, _1081 + _910)))) * _932))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1022) * half(_1022)) / fast::max(_1008, 9.9999997473787516355514526367188e-05)) * half(_1041)) * half(_1041)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1244 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1247 = dot(_1244, _1244);
    float3 _1252 = _1244 * rsqrt(fast::max(_1247, 9.9999999392252902907785028219223e-09));
    float _1256 = _1247 * float(frame.punctualLights[1].positionFalloff.w);
    float _1261 = fast::clamp(fma(-_1256, _1256, 1.0), 0.0, 1.0);
    float _1280 = fast::clamp(fma(dot(-_1252, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1318 = dot(_650, half3(_1252));
    half _1320 = clamp(_1318, half(0.0), half(1.0));
    half _1334 = clamp(dot(_650, half3(fast::normalize(_656 + _1252))), half(0.0), half(1.0));
    half3 _1373 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1318 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1320), half3(float3(0.0)), half3(float3(1.0)))) * _930) + (_961 * ((((_1179 * pow(max(fma(half(-float(_1334)), _1334, half(1.0)), half(0.0)), _1182)) * half(0.15915493667125701904296875)) * (_1320 / (half(4.0) * fma(half(-float(_1320)), _910, _1320 + _910)))) * _932))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1261) * half(_1261)) / fast::max(_1247, 9.9999997473787516355514526367188e-05)) * half(_1280)) * half(_1280)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_968).xyz, _961 * _928, (half3(float3(params.facet_diffuseColor)) * _870) * _930) + _1134) + _1373, half(1.0)));
    return out;
}

