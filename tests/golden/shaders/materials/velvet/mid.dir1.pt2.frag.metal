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
    half3 _604 = normalize(half3(in.v_normal));
    float3 _610 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _818 = max(dot(_604, half3(_610)), half(9.9999997473787516355514526367188e-05));
    float4 _823 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_818, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _877 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1664 = half4(_823);
    half _836 = _1664.z;
    half _838 = fma(half(-float(max(_877.x, max(_877.y, _877.z)))), _836, half(1.0));
    half4 _1668 = half4(_823);
    half _843 = _1668.w;
    float4 _896 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_610), _604)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _642 = half4(frame.lightDirection).xyz;
    half _919 = dot(_604, _642);
    half _921 = clamp(_919, half(0.0), half(1.0));
    half _933 = clamp(dot(_604, normalize(half3(_610) + _642)), half(0.0), half(1.0));
    half _1002 = half(8192.0) * fma(half(-float(_921)), _818, _921 + _818);
    half _1006 = half(1.0) / (half(params.facet_alpha) * _1002);
    half _1013 = half(2048.0) * half(params.facet_alpha);
    float3 _1077 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1080 = dot(_1077, _1077);
    float3 _1085 = _1077 * rsqrt(fast::max(_1080, 9.9999999392252902907785028219223e-09));
    float _1089 = _1080 * float(frame.punctualLights[0].positionFalloff.w);
    float _1094 = fast::clamp(fma(-_1089, _1089, 1.0), 0.0, 1.0);
    float _1113 = fast::clamp(fma(dot(-_1085, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1147 = dot(_604, half3(_1085));
    half _1149 = clamp(_1147, half(0.0), half(1.0));
    half _1161 = clamp(dot(_604, normalize(half3(_610) + half3(_1085))), half(0.0), half(1.0));
    half _1230 = half(8192.0) * fma(half(-float(_1149)), _818, _1149 + _818);
    half _1234 = half(1.0) / (half(params.facet_alpha) * _1230);
    half3 _1194 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1147 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1149), half3(float3(0.0)), half3(float3(1.0)))) * _838) + (_877 * ((((fma(_1234, _1230, half(2.0)) * pow(max(fma(half(-float(_1161)), _1161, half(1.0)), half(0.0)), half(0.5) * (_1234 * _1230))) * half(0.15915493667125701904296875)) * (_1149 * (_1234 * _1013))) * _843))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1094) * half(_1094)) / fast::max(_1080, 9.9999997473787516355514526367188e-05)) * half(_1113)) * half(_1113)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1269 = (fma(half4(_896).xyz, _877 * _836, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _604.y)) + (half4(frame.sh[2]).xyz * _604.z)) + (half4(frame.sh[3]).xyz * _604.x), half3(float3(0.0)))) * _838) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_919 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_921), half3(float3(0.0)), half3(float3(1.0)))) * _838) + (_877 * ((((fma(_1006, _1002, half(2.0)) * pow(max(fma(half(-float(_933)), _933, half(1.0)), half(0.0)), half(0.5) * (_1006 * _1002))) * half(0.15915493667125701904296875)) * (_921 * (_1006 * _1013))) * _843))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1194;
    float3 _1305 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1308 = dot(_1305, _1305);
    float3 _1313 = _1305 * rsqrt(fast::max(_1308, 9.9999999392252902907785028219223e-09));
    float _1317 = _1308 * float(frame.punctualLights[1].positionFalloff.w);
    float _1322 = fast::clamp(fma(-_1317, _1317, 1.0), 0.0, 1.0);
    float _1341 = fast::clamp(fma(dot(-_1313, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1375 = dot(_604, half3(_1313));
    half _1377 = clamp(_1375, half(0.0), half(1.0));
    half _1389 = clamp(dot(_604, normalize(half3(_610) + half3(_1313))), half(0.0), half(1.0));
    half _1458 = half(8192.0) * fma(half(-float(_1377)), _818, _1377 + _818);
    half _1462 = half(1.0) / (half(params.facet_alpha) * _1458);
    half3 _1422 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1375 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1377), half3(float3(0.0)), half3(float3(1.0)))) * _838) + (_877 * ((((fma(_1462, _1458, half(2.0)) * pow(max(fma(half(-float(_1389)), _1389, half(1.0)), half(0.0)), half(0.5) * (_1462 * _1458))) * half(0.15915493667125701904296875)) * (_1377 * (_1462 * _1013))) * _843))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1322) * half(_1322)) / fast::max(_1308, 9.9999997473787516355514526367188e-05)) * half(_1341)) * half(_1341)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1497 = _1269 + _1422;
    out.fragColor = float4(half4(_1497, half(1.0)));
    return out;
}

