#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    half3 _585 = normalize(half3(in.v_normal));
    float3 _601 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _780 = max(dot(_585, half3(_601)), half(9.9999997473787516355514526367188e-05));
    float4 _819 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_780, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _838 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_819).y) - half(1.0)));
    float4 _845 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_601), _585)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _638 = half4(frame.lightDirection).xyz;
    half3 _952 = normalize(half3(_601) + _638);
    half _903 = clamp(dot(_585, _638), half(0.0), half(1.0));
    half3 _1015 = cross(_585, _952) * half(64.0);
    half _1018 = half(64.0) * half(params.facet_alpha);
    half _1019 = clamp(dot(_585, _952), half(0.0), half(1.0)) * _1018;
    half _995 = half(4096.0) * half(params.facet_alpha);
    half _998 = half(6.283185482025146484375) * max(mix((half(2.0) * _903) * _780, _903 + _780, half(params.facet_alpha)), half(0.000244140625));
    half _1000 = _995 / (fma(_1019, _1019, dot(_1015, _1015)) * _998);
    float3 _1067 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1070 = dot(_1067, _1067);
    float3 _1075 = _1067 * rsqrt(fast::max(_1070, 9.9999999392252902907785028219223e-09));
    float _1079 = _1070 * float(frame.punctualLights[0].positionFalloff.w);
    float _1084 = fast::clamp(fma(-_1079, _1079, 1.0), 0.0, 1.0);
    float _1103 = fast::clamp(fma(dot(-_1075, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1213 = normalize(half3(_601) + half3(_1075));
    half _1164 = clamp(dot(_585, half3(_1075)), half(0.0), half(1.0));
    half3 _1276 = cross(_585, _1213) * half(64.0);
    half _1280 = clamp(dot(_585, _1213), half(0.0), half(1.0)) * _1018;
    half _1259 = half(6.283185482025146484375) * max(mix((half(2.0) * _1164) * _780, _1164 + _780, half(params.facet_alpha)), half(0.000244140625));
    half _1261 = _995 / (fma(_1280, _1280, dot(_1276, _1276)) * _1259);
    float3 _1328 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1331 = dot(_1328, _1328);
    float3 _1336 = _1328 * rsqrt(fast::max(_1331, 9.9999999392252902907785028219223e-09));
    float _1340 = _1331 * float(frame.punctualLights[1].positionFalloff.w);
    float _1345 = fast::clamp(fma(-_1340, _1340, 1.0), 0.0, 1.0);
    float _1364 = fast::clamp(fma(dot(-_1336, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1474 = normalize(half3(_601) + half3(_1336));
    half _1425 = clamp(dot(_585, half3(_1336)), half(0.0), half(1.0));
    half3 _1537 = cross(_585, _1474) * half(64.0);
    half _1541 = clamp(dot(_585, _1474), half(0.0), half(1.0)) * _1018;
    half _1520 = half(6.283185482025146484375) * max(mix((half(2.0) * _1425) * _780, _1425 + _780, half(params.facet_alpha)), half(0.000244140625));
    half _1522 = _995 / (fma(_1541, _1541, dot(_1537, _1537)) * _1520);
    half3 _1553 = (fma(half4(_845).xyz, mix(half4(_819).xxx, half4(_819).yyy, half3(float3(params.facet_f0))) * _838, min(((half3(float3(params.facet_f0)) * min(_1000 * (_1000 * _998), half(65504.0))) * _838) * (half4(frame.lightColor).xyz * _903), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1261 * (_1261 * _1259), half(65504.0))) * _838) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1084) * half(_1084)) / fast::max(_1070, 9.9999997473787516355514526367188e-05)) * half(_1103)) * half(_1103)), float3(65504.0))) * _1164), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1522 * (_1522 * _1520), half(65504.0))) * _838) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1345) * half(_1345)) / fast::max(_1331, 9.9999997473787516355514526367188e-05)) * half(_1364)) * half(_1364)), float3(65504.0))) * _1425), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1553, half(1.0)));
    return out;
}

