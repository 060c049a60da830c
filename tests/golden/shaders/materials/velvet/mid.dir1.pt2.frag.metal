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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _502 = normalize(half3(in.v_normal));
    float3 _518 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _681 = max(dot(_502, half3(_518)), half(9.9999997473787516355514526367188e-05));
    float4 _686 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_681, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _740 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1393 = half4(_686);
    half _699 = _1393.z;
    half4 _1397 = half4(_686);
    half _706 = _1397.w;
    float4 _756 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_518), _502)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _553 = half4(frame.lightDirection).xyz;
    half _778 = clamp(dot(_502, _553), half(0.0), half(1.0));
    half _790 = clamp(dot(_502, normalize(half3(_518) + _553)), half(0.0), half(1.0));
    half _835 = half(8192.0) * fma(half(-float(_778)), _681, _778 + _681);
    half _839 = half(1.0) / (half(params.facet_alpha) * _835);
    half _846 = half(2048.0) * half(params.facet_alpha);
    float3 _904 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _907 = dot(_904, _904);
    float3 _912 = _904 * rsqrt(fast::max(_907, 9.9999999392252902907785028219223e-09));
    float _916 = _907 * float(frame.punctualLights[0].positionFalloff.w);
    float _921 = fast::clamp(fma(-_916, _916, 1.0), 0.0, 1.0);
    float _940 = fast::clamp(fma(dot(-_912, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _973 = clamp(dot(_502, half3(_912)), half(0.0), half(1.0));
    half _985 = clamp(dot(_502, normalize(half3(_518) + half3(_912))), half(0.0), half(1.0));
    half _1030 = half(8192.0) * fma(half(-float(_973)), _681, _973 + _681);
    half _1034 = half(1.0) / (half(params.facet_alpha) * _1030);
    float3 _1099 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1102 = dot(_1099, _1099);
    float3 _1107 = _1099 * rsqrt(fast::max(_1102, 9.9999999392252902907785028219223e-09));
    float _1111 = _1102 * float(frame.punctualLights[1].positionFalloff.w);
    float _1116 = fast::clamp(fma(-_1111, _1111, 1.0), 0.0, 1.0);
    float _1135 = fast::clamp(fma(dot(-_1107, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1168 = clamp(dot(_502, half3(_1107)), half(0.0), half(1.0));
    half _1180 = clamp(dot(_502, normalize(half3(_518) + half3(_1107))), half(0.0), half(1.0));
    half _1225 = half(8192.0) * fma(half(-float(_1168)), _681, _1168 + _681);
    half _1229 = half(1.0) / (half(params.facet_alpha) * _1225);
    half3 _1258 = ((fma(half4(_756).xyz, _740 * _699, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_740.x, max(_740.y, _740.z)))), _699, half(1.0))) + min((_740 * ((((fma(_839, _835, half(2.0)) * pow(max(fma(half(-float(_790)), _790, half(1.0)), half(0.0)), half(0.5) * (_839 * _835))) * half(0.15915493667125701904296875)) * (_778 * (_839 * _846))) * _706)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_740 * ((((fma(_1034, _1030, half(2.0)) * pow(max(fma(half(-float(_985)), _985, half(1.0)), half(0.0)), half(0.5) * (_1034 * _1030))) * half(0.15915493667125701904296875)) * (_973 * (_1034 * _846))) * _706)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_921) * half(_921)) / fast::max(_907, 9.9999997473787516355514526367188e-05)) * half(_940)) * half(_940)), float3(65504.0))), half3(float3(65504.0)))) + min((_740 * ((((fma(_1229, _1225, half(2.0)) * pow(max(fma(half(-float(_1180)), _1180, half(1.0)), half(0.0)), half(0.5) * (_1229 * _1225))) * half(0.15915493667125701904296875)) * (_1168 * (_1229 * _846))) * _706)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1116) * half(_1116)) / fast::max(_1102, 9.9999997473787516355514526367188e-05)) * half(_1135)) * half(_1135)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1258, half(1.0)));
    return out;
}

