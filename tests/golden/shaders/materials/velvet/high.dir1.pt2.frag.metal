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
    half _838 = _673.y;
    half _843 = _673.z;
    half _848 = _673.x;
    half3 _916 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _838)) + (half4(frame.sh[2]).xyz * _843)) + (half4(frame.sh[3]).xyz * _848)) + (((((half4(frame.sh[4]).xyz * (_848 * _838)) + (half4(frame.sh[5]).xyz * (_838 * _843))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _843, _843, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_848 * _843))) + (half4(frame.sh[8]).xyz * fma(_848, _848, half(-float(_838 * _838))))), half3(float3(0.0)));
    half _957 = max(dot(_673, half3(_679)), half(9.9999997473787516355514526367188e-05));
    float4 _962 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_957, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1016 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1835 = half4(_962);
    half _975 = _1835.z;
    half _977 = fma(half(-float(max(_1016.x, max(_1016.y, _1016.z)))), _975, half(1.0));
    half4 _1839 = half4(_962);
    half _982 = _1839.w;
    float4 _1032 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_679), _673)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1055 = dot(_673, half3(frame.lightDirection.xyz));
    half _1057 = clamp(_1055, half(0.0), half(1.0));
    half _1069 = clamp(dot(_673, half3(fast::normalize(_679 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1140 = half(8192.0) * fma(half(-float(_1057)), _957, _1057 + _957);
    half _1144 = half(1.0) / (half(params.facet_alpha) * _1140);
    half _1151 = half(2048.0) * half(params.facet_alpha);
    float3 _1215 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1218 = dot(_1215, _1215);
    float3 _1223 = _1215 * rsqrt(fast::max(_1218, 9.9999999392252902907785028219223e-09));
    float _1227 = _1218 * float(frame.punctualLights[0].positionFalloff.w);
    float _1232 = fast::clamp(fma(-_1227, _1227, 1.0), 0.0, 1.0);
    float _1251 = fast::clamp(fma(dot(-_1223, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1285 = dot(_673, half3(_1223));
    half _1287 = clamp(_1285, half(0.0), half(1.0));
    half _1299 = clamp(dot(_673, half3(fast::normalize(_679 + _1223))), half(0.0), half(1.0));
    half _1370 = half(8192.0) * fma(half(-float(_1287)), _957, _1287 + _957);
    half _1374 = half(1.0) / (half(params.facet_alpha) * _1370);
    half3 _1332 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1285 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1287), half3(float3(0.0)), half3(float3(1.0)))) * _977) + (_1016 * ((((fma(_1374, _1370, half(2.0)) * pow(max(fma(half(-float(_1299)), _1299, half(1.0)), half(0.0)), half(0.5) * (_1374 * _1370))) * half(0.15915493667125701904296875)) * (_1287 * (_1374 * _1151))) * _982))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1232) * half(_1232)) / fast::max(_1218, 9.9999997473787516355514526367188e-05)) * half(_1251)) * half(_1251)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1409 = (fma(half4(_1032).xyz, _1016 * _975, (half3(float3(params.facet_diffuseColor)) * _916) * _977) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1055 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1057), half3(float3(0.0)), half3(float3(1.0)))) * _977) + (_1016 * ((((fma(_1144, _1140, half(2.0)) * pow(max(fma(half(-float(_1069)), _1069, half(1.0)), half(0.0)), half(0.5) * (_1144 * _1140))) * half(0.15915493667125701904296875)) * (_1057 * (_1144 * _1151))) * _982))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1332;
    float3 _1445 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1448 = dot(_1445, _1445);
    float3 _1453 = _1445 * rsqrt(fast::max(_1448, 9.9999999392252902907785028219223e-09));
    float _1457 = _1448 * float(frame.punctualLights[1].positionFalloff.w);
    float _1462 = fast::clamp(fma(-_1457, _1457, 1.0), 0.0, 1.0);
    float _1481 = fast::clamp(fma(dot(-_1453, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1515 = dot(_673, half3(_1453));
    half _1517 = clamp(_1515, half(0.0), half(1.0));
    half _1529 = clamp(dot(_673, half3(fast::normalize(_679 + _1453))), half(0.0), half(1.0));
    half _1600 = half(8192.0) * fma(half(-float(_1517)), _957, _1517 + _957);
    half _1604 = half(1.0) / (half(params.facet_alpha) * _1600);
    half3 _1562 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1515 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1517), half3(float3(0.0)), half3(float3(1.0)))) * _977) + (_1016 * ((((fma(_1604, _1600, half(2.0)) * pow(max(fma(half(-float(_1529)), _1529, half(1.0)), half(0.0)), half(0.5) * (_1604 * _1600))) * half(0.15915493667125701904296875)) * (_1517 * (_1604 * _1151))) * _982))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1462) * half(_1462)) / fast::max(_1448, 9.9999997473787516355514526367188e-05)) * half(_1481)) * half(_1481)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1409 + _1562, half(1.0)));
    return out;
}

