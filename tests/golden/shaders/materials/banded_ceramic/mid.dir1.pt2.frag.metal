#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    half3 _651 = normalize(half3(in.v_normal));
    float3 _667 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _813 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _921 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _813)), half(0.0), half(1.0));
    half3 _929 = half3((half(0.1599999964237213134765625) * _921) * _921);
    half _938 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _813)), half(0.08900000154972076416015625), half(1.0));
    half _881 = max(dot(_651, half3(_667)), half(9.9999997473787516355514526367188e-05));
    float4 _945 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_881, _938)), level(0.0));
    half3 _964 = half3(float3(1.0)) + (_929 * ((half(1.0) / half4(_945).y) - half(1.0)));
    float4 _971 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_667), _651)), level(_938 * half(4.0)));
    half3 _704 = half4(frame.lightDirection).xyz;
    half _1102 = _938 * _938;
    half3 _1113 = normalize(half3(_667) + _704);
    half _1029 = clamp(dot(_651, _704), half(0.0), half(1.0));
    half4 _1182 = half4(cross(_651, _1113), _1102 * clamp(dot(_651, _1113), half(0.0), half(1.0))) * half(64.0);
    half _1156 = half(4096.0) * _1102;
    half _1159 = half(6.283185482025146484375) * max(mix((half(2.0) * _1029) * _881, _1029 + _881, _1102), half(0.000244140625));
    half _1161 = _1156 / (dot(_1182, _1182) * _1159);
    float3 _1226 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1229 = dot(_1226, _1226);
    float3 _1234 = _1226 * rsqrt(fast::max(_1229, 9.9999999392252902907785028219223e-09));
    float _1238 = _1229 * float(frame.punctualLights[0].positionFalloff.w);
    float _1243 = fast::clamp(fma(-_1238, _1238, 1.0), 0.0, 1.0);
    float _1262 = fast::clamp(fma(dot(-_1234, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1407 = normalize(half3(_667) + half3(_1234));
    half _1323 = clamp(dot(_651, half3(_1234)), half(0.0), half(1.0));
    half4 _1476 = half4(cross(_651, _1407), _1102 * clamp(dot(_651, _1407), half(0.0), half(1.0))) * half(64.0);
    half _1453 = half(6.283185482025146484375) * max(mix((half(2.0) * _1323) * _881, _1323 + _881, _1102), half(0.000244140625));
    half _1455 = _1156 / (dot(_1476, _1476) * _1453);
    float3 _1520 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1523 = dot(_1520, _1520);
    float3 _1528 = _1520 * rsqrt(fast::max(_1523, 9.9999999392252902907785028219223e-09));
    float _1532 = _1523 * float(frame.punctualLights[1].positionFalloff.w);
    float _1537 = fast::clamp(fma(-_1532, _1532, 1.0), 0.0, 1.0);
    float _1556 = fast::clamp(fma(dot(-_1528, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1701 = normalize(half3(_667) + half3(_1528));
    half _1617 = clamp(dot(_651, half3(_1528)), half(0.0), half(1.0));
    half4 _1770 = half4(cross(_651, _1701), _1102 * clamp(dot(_651, _1701), half(0.0), half(1.0))) * half(64.0);
    half _1747 = half(6.283185482025146484375) * max(mix((half(2.0) * _1617) * _881, _1617 + _881, _1102), half(0.000244140625));
    half _1749 = _1156 / (dot(_1770, _1770) * _1747);
    half3 _1778 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_813))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_971).xyz * (mix(half4(_945).xxx, half4(_945).yyy, _929) * _964)) + min(((_929 * min(_1161 * (_1161 * _1159), half(65504.0))) * _964) * (half4(frame.lightColor).xyz * _1029), half3(float3(65504.0)))) + min(((_929 * min(_1455 * (_1455 * _1453), half(65504.0))) * _964) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1243) * half(_1243)) / fast::max(_1229, 9.9999997473787516355514526367188e-05)) * half(_1262)) * half(_1262)), float3(65504.0))) * _1323), half3(float3(65504.0)))) + min(((_929 * min(_1749 * (_1749 * _1747), half(65504.0))) * _964) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1537) * half(_1537)) / fast::max(_1523, 9.9999997473787516355514526367188e-05)) * half(_1556)) * half(_1556)), float3(65504.0))) * _1617), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1778, half(1.0)));
    return out;
}

