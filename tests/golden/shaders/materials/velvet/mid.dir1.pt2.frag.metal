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
    half3 _585 = normalize(half3(in.v_normal));
    float3 _591 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _797 = max(dot(_585, half3(_591)), half(9.9999997473787516355514526367188e-05));
    float4 _802 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_797, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1630 = half4(_802);
    half _815 = _1630.z;
    half _817 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _815, half(1.0));
    half4 _1634 = half4(_802);
    half _822 = _1634.w;
    float4 _831 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_591), _585)), level(params.facet_sheenLod));
    half3 _623 = half4(frame.lightDirection).xyz;
    half _887 = dot(_585, _623);
    half _889 = clamp(_887, half(0.0), half(1.0));
    half _901 = clamp(dot(_585, normalize(half3(_591) + _623)), half(0.0), half(1.0));
    half _970 = half(8192.0) * fma(half(-float(_889)), _797, _889 + _797);
    half _974 = half(1.0) / (half(params.facet_alpha) * _970);
    half _981 = half(2048.0) * half(params.facet_alpha);
    float3 _1045 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1048 = dot(_1045, _1045);
    float3 _1053 = _1045 * rsqrt(fast::max(_1048, 9.9999999392252902907785028219223e-09));
    float _1057 = _1048 * float(frame.punctualLights[0].positionFalloff.w);
    float _1062 = fast::clamp(fma(-_1057, _1057, 1.0), 0.0, 1.0);
    float _1081 = fast::clamp(fma(dot(-_1053, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1115 = dot(_585, half3(_1053));
    half _1117 = clamp(_1115, half(0.0), half(1.0));
    half _1129 = clamp(dot(_585, normalize(half3(_591) + half3(_1053))), half(0.0), half(1.0));
    half _1198 = half(8192.0) * fma(half(-float(_1117)), _797, _1117 + _797);
    half _1202 = half(1.0) / (half(params.facet_alpha) * _1198);
    half3 _1162 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1115 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1117), half3(float3(0.0)), half3(float3(1.0)))) * _817) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1202, _1198, half(2.0)) * pow(max(fma(half(-float(_1129)), _1129, half(1.0)), half(0.0)), half(0.5) * (_1202 * _1198))) * half(0.15915493667125701904296875)) * (_1117 * (_1202 * _981))) * _822))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1062) * half(_1062)) / fast::max(_1048, 9.9999997473787516355514526367188e-05)) * half(_1081)) * half(_1081)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1237 = (fma(half4(_831).xyz, half3(float3(params.facet_sheenColor)) * _815, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _585.y)) + (half4(frame.sh[2]).xyz * _585.z)) + (half4(frame.sh[3]).xyz * _585.x), half3(float3(0.0)))) * _817) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_887 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_889), half3(float3(0.0)), half3(float3(1.0)))) * _817) + (half3(float3(params.facet_sheenColor)) * ((((fma(_974, _970, half(2.0)) * pow(max(fma(half(-float(_901)), _901, half(1.0)), half(0.0)), half(0.5) * (_974 * _970))) * half(0.15915493667125701904296875)) * (_889 * (_974 * _981))) * _822))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1162;
    float3 _1273 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1276 = dot(_1273, _1273);
    float3 _1281 = _1273 * rsqrt(fast::max(_1276, 9.9999999392252902907785028219223e-09));
    float _1285 = _1276 * float(frame.punctualLights[1].positionFalloff.w);
    float _1290 = fast::clamp(fma(-_1285, _1285, 1.0), 0.0, 1.0);
    float _1309 = fast::clamp(fma(dot(-_1281, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1343 = dot(_585, half3(_1281));
    half _1345 = clamp(_1343, half(0.0), half(1.0));
    half _1357 = clamp(dot(_585, normalize(half3(_591) + half3(_1281))), half(0.0), half(1.0));
    half _1426 = half(8192.0) * fma(half(-float(_1345)), _797, _1345 + _797);
    half _1430 = half(1.0) / (half(params.facet_alpha) * _1426);
    half3 _1390 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1343 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1345), half3(float3(0.0)), half3(float3(1.0)))) * _817) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1430, _1426, half(2.0)) * pow(max(fma(half(-float(_1357)), _1357, half(1.0)), half(0.0)), half(0.5) * (_1430 * _1426))) * half(0.15915493667125701904296875)) * (_1345 * (_1430 * _981))) * _822))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1290) * half(_1290)) / fast::max(_1276, 9.9999997473787516355514526367188e-05)) * half(_1309)) * half(_1309)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1465 = _1237 + _1390;
    out.fragColor = float4(half4(_1465, half(1.0)));
    return out;
}

