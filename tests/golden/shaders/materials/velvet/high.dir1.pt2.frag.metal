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
    half _836 = _673.y;
    half _841 = _673.z;
    half _846 = _673.x;
    half3 _914 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _836)) + (half4(frame.sh[2]).xyz * _841)) + (half4(frame.sh[3]).xyz * _846)) + (((((half4(frame.sh[4]).xyz * (_846 * _836)) + (half4(frame.sh[5]).xyz * (_836 * _841))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _841, _841, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_846 * _841))) + (half4(frame.sh[8]).xyz * fma(_846, _846, half(-float(_836 * _836))))), half3(float3(0.0)));
    half _955 = max(dot(_673, half3(_679)), half(9.9999997473787516355514526367188e-05));
    float4 _960 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_955, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1014 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1833 = half4(_960);
    half _973 = _1833.z;
    half _975 = fma(half(-float(max(_1014.x, max(_1014.y, _1014.z)))), _973, half(1.0));
    half4 _1837 = half4(_960);
    half _980 = _1837.w;
    float4 _1030 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_679), _673)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1053 = dot(_673, half3(frame.lightDirection.xyz));
    half _1055 = clamp(_1053, half(0.0), half(1.0));
    half _1067 = clamp(dot(_673, half3(fast::normalize(_679 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1138 = half(8192.0) * fma(half(-float(_1055)), _955, _1055 + _955);
    half _1142 = half(1.0) / (half(params.facet_alpha) * _1138);
    half _1149 = half(2048.0) * half(params.facet_alpha);
    float3 _1213 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1216 = dot(_1213, _1213);
    float3 _1221 = _1213 * rsqrt(fast::max(_1216, 9.9999999392252902907785028219223e-09));
    float _1225 = _1216 * float(frame.punctualLights[0].positionFalloff.w);
    float _1230 = fast::clamp(fma(-_1225, _1225, 1.0), 0.0, 1.0);
    float _1249 = fast::clamp(fma(dot(-_1221, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1283 = dot(_673, half3(_1221));
    half _1285 = clamp(_1283, half(0.0), half(1.0));
    half _1297 = clamp(dot(_673, half3(fast::normalize(_679 + _1221))), half(0.0), half(1.0));
    half _1368 = half(8192.0) * fma(half(-float(_1285)), _955, _1285 + _955);
    half _1372 = half(1.0) / (half(params.facet_alpha) * _1368);
    half3 _1330 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1283 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1285), half3(float3(0.0)), half3(float3(1.0)))) * _975) + (_1014 * ((((fma(_1372, _1368, half(2.0)) * pow(max(fma(half(-float(_1297)), _1297, half(1.0)), half(0.0)), half(0.5) * (_1372 * _1368))) * half(0.15915493667125701904296875)) * (_1285 * (_1372 * _1149))) * _980))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1230) * half(_1230)) / fast::max(_1216, 9.9999997473787516355514526367188e-05)) * half(_1249)) * half(_1249)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1407 = (fma(half4(_1030).xyz, _1014 * _973, (half3(float3(params.facet_diffuseColor)) * _914) * _975) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1053 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1055), half3(float3(0.0)), half3(float3(1.0)))) * _975) + (_1014 * ((((fma(_1142, _1138, half(2.0)) * pow(max(fma(half(-float(_1067)), _1067, half(1.0)), half(0.0)), half(0.5) * (_1142 * _1138))) * half(0.15915493667125701904296875)) * (_1055 * (_1142 * _1149))) * _980))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1330;
    float3 _1443 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1446 = dot(_1443, _1443);
    float3 _1451 = _1443 * rsqrt(fast::max(_1446, 9.9999999392252902907785028219223e-09));
    float _1455 = _1446 * float(frame.punctualLights[1].positionFalloff.w);
    float _1460 = fast::clamp(fma(-_1455, _1455, 1.0), 0.0, 1.0);
    float _1479 = fast::clamp(fma(dot(-_1451, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1513 = dot(_673, half3(_1451));
    half _1515 = clamp(_1513, half(0.0), half(1.0));
    half _1527 = clamp(dot(_673, half3(fast::normalize(_679 + _1451))), half(0.0), half(1.0));
    half _1598 = half(8192.0) * fma(half(-float(_1515)), _955, _1515 + _955);
    half _1602 = half(1.0) / (half(params.facet_alpha) * _1598);
    half3 _1560 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1513 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1515), half3(float3(0.0)), half3(float3(1.0)))) * _975) + (_1014 * ((((fma(_1602, _1598, half(2.0)) * pow(max(fma(half(-float(_1527)), _1527, half(1.0)), half(0.0)), half(0.5) * (_1602 * _1598))) * half(0.15915493667125701904296875)) * (_1515 * (_1602 * _1149))) * _980))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1460) * half(_1460)) / fast::max(_1446, 9.9999997473787516355514526367188e-05)) * half(_1479)) * half(_1479)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1407 + _1560, half(1.0)));
    return out;
}

