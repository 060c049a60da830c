#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _761 = normalize(half3(in.v_normal));
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _937 = max(dot(_761, half3(_777)), half(9.9999997473787516355514526367188e-05));
    half3 _941 = reflect(-half3(_777), _761);
    float4 _976 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_937, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _995 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_976).y) - half(1.0)));
    float4 _1007 = facet_environment.sample(facet_environmentSmplr, float3(_941), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1084 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1041 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_937, _1084)), level(0.0));
    half3 _1091 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1923 = half4(_1041);
    half _1054 = _1923.z;
    half _1056 = fma(half(-float(max(_1091.x, max(_1091.y, _1091.z)))), _1054, half(1.0));
    half _1100 = _1084 * _1084;
    half4 _1927 = half4(_1041);
    half _1061 = _1927.w;
    float4 _1117 = facet_environment.sample(facet_environmentSmplr, float3(_941), level(_1084 * (half(4.0) * (half(2.0) - _1084))));
    float3 _1154 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1157 = dot(_1154, _1154);
    float3 _1162 = _1154 * rsqrt(fast::max(_1157, 9.9999999392252902907785028219223e-09));
    float _1166 = _1157 * float(frame.punctualLights[0].positionFalloff.w);
    float _1171 = fast::clamp(fma(-_1166, _1166, 1.0), 0.0, 1.0);
    float _1190 = fast::clamp(fma(dot(-_1162, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1201 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1171) * half(_1171)) / fast::max(_1157, 9.9999997473787516355514526367188e-05)) * half(_1190)) * half(_1190)), float3(65504.0));
    half3 _1317 = normalize(half3(_777) + half3(_1162));
    half _1256 = clamp(dot(_761, half3(_1162)), half(0.0), half(1.0));
    half _1260 = clamp(dot(_761, _1317), half(0.0), half(1.0));
    half3 _1344 = cross(_761, _1317);
    half _1347 = _1260 * half(params.facet_alpha);
    half _1361 = _1256 + _937;
    half _1364 = max(mix((half(2.0) * _1256) * _937, _1361, half(params.facet_alpha)), half(0.000244140625));
    half _1366 = half(1024.0) * half(params.facet_alpha);
    half _1371 = _1366 / (fma(_1347, _1347, dot(_1344, _1344)) * (half(6433.98193359375) * _1364));
    half _1408 = half(8192.0) * fma(half(-float(_1256)), _937, _1361);
    half _1412 = half(1.0) / (_1100 * _1408);
    half _1419 = half(2048.0) * _1100;
    float3 _1477 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1480 = dot(_1477, _1477);
    float3 _1485 = _1477 * rsqrt(fast::max(_1480, 9.9999999392252902907785028219223e-09));
    float _1489 = _1480 * float(frame.punctualLights[1].positionFalloff.w);
    float _1494 = fast::clamp(fma(-_1489, _1489, 1.0), 0.0, 1.0);
    float _1513 = fast::clamp(fma(dot(-_1485, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1524 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1494) * half(_1494)) / fast::max(_1480, 9.9999997473787516355514526367188e-05)) * half(_1513)) * half(_1513)), float3(65504.0));
    half3 _1640 = normalize(half3(_777) + half3(_1485));
    half _1579 = clamp(dot(_761, half3(_1485)), half(0.0), half(1.0));
    half _1583 = clamp(dot(_761, _1640), half(0.0), half(1.0));
    half3 _1667 = cross(_761, _1640);
    half _1670 = _1583 * half(params.facet_alpha);
    half _1684 = _1579 + _937;
    half _1687 = max(mix((half(2.0) * _1579) * _937, _1684, half(params.facet_alpha)), half(0.000244140625));
    half _1694 = _1366 / (fma(_1670, _1670, dot(_1667, _1667)) * (half(6433.98193359375) * _1687));
    half _1731 = half(8192.0) * fma(half(-float(_1579)), _937, _1684);
    half _1735 = half(1.0) / (_1100 * _1731);
    half3 _1764 = (fma(half4(_1117).xyz, _1091 * _1054, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1007).xyz * (mix(half4(_976).xxx, half4(_976).yyy, half3(float3(params.facet_f0))) * _995)) * _1056) + min(fma((half3(float3(params.facet_f0)) * min(_1371 * (_1371 * (half(6.283185482025146484375) * _1364)), half(65504.0))) * _995, (half3(_1201) * _1256) * _1056, (_1091 * ((((fma(_1412, _1408, half(2.0)) * pow(max(fma(half(-float(_1260)), _1260, half(1.0)), half(0.0)), half(0.5) * (_1412 * _1408))) * half(0.15915493667125701904296875)) * (_1256 * (_1412 * _1419))) * _1061)) * half3(_1201)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1694 * (_1694 * (half(6.283185482025146484375) * _1687)), half(65504.0))) * _995, (half3(_1524) * _1579) * _1056, (_1091 * ((((fma(_1735, _1731, half(2.0)) * pow(max(fma(half(-float(_1583)), _1583, half(1.0)), half(0.0)), half(0.5) * (_1735 * _1731))) * half(0.15915493667125701904296875)) * (_1579 * (_1735 * _1419))) * _1061)) * half3(_1524)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1764, half(1.0)));
    return out;
}

