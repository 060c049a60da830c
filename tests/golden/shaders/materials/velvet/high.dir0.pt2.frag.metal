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
    half3 _657 = normalize(half3(in.v_normal));
    float3 _663 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _799 = _657.y;
    half _804 = _657.z;
    half _809 = _657.x;
    half3 _877 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _799)) + (half4(frame.sh[2]).xyz * _804)) + (half4(frame.sh[3]).xyz * _809)) + (((((half4(frame.sh[4]).xyz * (_809 * _799)) + (half4(frame.sh[5]).xyz * (_799 * _804))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _804, _804, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_809 * _804))) + (half4(frame.sh[8]).xyz * fma(_809, _809, half(-float(_799 * _799))))), half3(float3(0.0)));
    half _916 = max(dot(_657, half3(_663)), half(9.9999997473787516355514526367188e-05));
    float4 _921 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_916, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1619 = half4(_921);
    half _934 = _1619.z;
    half _936 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _934, half(1.0));
    half4 _1623 = half4(_921);
    half _941 = _1623.w;
    float4 _950 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_663), _657)), level(params.facet_sheenLod));
    float3 _1020 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1023 = dot(_1020, _1020);
    float3 _1028 = _1020 * rsqrt(fast::max(_1023, 9.9999999392252902907785028219223e-09));
    float _1032 = _1023 * float(frame.punctualLights[0].positionFalloff.w);
    float _1037 = fast::clamp(fma(-_1032, _1032, 1.0), 0.0, 1.0);
    float _1056 = fast::clamp(fma(dot(-_1028, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1090 = dot(_657, half3(_1028));
    half _1092 = clamp(_1090, half(0.0), half(1.0));
    half _1104 = clamp(dot(_657, half3(fast::normalize(_663 + _1028))), half(0.0), half(1.0));
    half _1175 = half(8192.0) * fma(half(-float(_1092)), _916, _1092 + _916);
    half _1179 = half(1.0) / (half(params.facet_alpha) * _1175);
    half _1186 = half(2048.0) * half(params.facet_alpha);
    half3 _1137 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1090 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1092), half3(float3(0.0)), half3(float3(1.0)))) * _936) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1179, _1175, half(2.0)) * pow(max(fma(half(-float(_1104)), _1104, half(1.0)), half(0.0)), half(0.5) * (_1179 * _1175))) * half(0.15915493667125701904296875)) * (_1092 * (_1179 * _1186))) * _941))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1037) * half(_1037)) / fast::max(_1023, 9.9999997473787516355514526367188e-05)) * half(_1056)) * half(_1056)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1250 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1253 = dot(_1250, _1250);
    float3 _1258 = _1250 * rsqrt(fast::max(_1253, 9.9999999392252902907785028219223e-09));
    float _1262 = _1253 * float(frame.punctualLights[1].positionFalloff.w);
    float _1267 = fast::clamp(fma(-_1262, _1262, 1.0), 0.0, 1.0);
    float _1286 = fast::clamp(fma(dot(-_1258, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1320 = dot(_657, half3(_1258));
    half _1322 = clamp(_1320, half(0.0), half(1.0));
    half _1334 = clamp(dot(_657, half3(fast::normalize(_663 + _1258))), half(0.0), half(1.0));
    half _1405 = half(8192.0) * fma(half(-float(_1322)), _916, _1322 + _916);
    half _1409 = half(1.0) / (half(params.facet_alpha) * _1405);
    half3 _1367 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1320 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1322), half3(float3(0.0)), half3(float3(1.0)))) * _936) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1409, _1405, half(2.0)) * pow(max(fma(half(-float(_1334)), _1334, half(1.0)), half(0.0)), half(0.5) * (_1409 * _1405))) * half(0.15915493667125701904296875)) * (_1322 * (_1409 * _1186))) * _941))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1267) * half(_1267)) / fast::max(_1253, 9.9999997473787516355514526367188e-05)) * half(_1286)) * half(_1286)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_950).xyz, half3(float3(params.facet_sheenColor)) * _934, (half3(float3(params.facet_diffuseColor)) * _877) * _936) + _1137) + _1367, half(1.0)));
    return out;
}

