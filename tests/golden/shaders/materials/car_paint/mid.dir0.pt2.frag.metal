#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
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
    half3 _649 = normalize(half3(in.v_normal));
    float3 _665 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _837 = max(dot(_649, half3(_665)), half(9.9999997473787516355514526367188e-05));
    half3 _841 = reflect(-half3(_665), _649);
    float4 _876 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_837, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _895 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_876).y) - half(1.0)));
    float4 _902 = facet_environment.sample(facet_environmentSmplr, float3(_841), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _947 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _950 = dot(_947, _947);
    float3 _955 = _947 * rsqrt(fast::max(_950, 9.9999999392252902907785028219223e-09));
    float _959 = _950 * float(frame.punctualLights[0].positionFalloff.w);
    float _964 = fast::clamp(fma(-_959, _959, 1.0), 0.0, 1.0);
    float _983 = fast::clamp(fma(dot(-_955, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1093 = normalize(half3(_665) + half3(_955));
    half _1044 = clamp(dot(_649, half3(_955)), half(0.0), half(1.0));
    half3 _1120 = cross(_649, _1093);
    half _1123 = clamp(dot(_649, _1093), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1140 = max(mix((half(2.0) * _1044) * _837, _1044 + _837, half(params.facet_alpha)), half(0.000244140625));
    half _1142 = half(1024.0) * half(params.facet_alpha);
    half _1147 = _1142 / (fma(_1123, _1123, dot(_1120, _1120)) * (half(6433.98193359375) * _1140));
    float3 _1195 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1198 = dot(_1195, _1195);
    float3 _1203 = _1195 * rsqrt(fast::max(_1198, 9.9999999392252902907785028219223e-09));
    float _1207 = _1198 * float(frame.punctualLights[1].positionFalloff.w);
    float _1212 = fast::clamp(fma(-_1207, _1207, 1.0), 0.0, 1.0);
    float _1231 = fast::clamp(fma(dot(-_1203, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1341 = normalize(half3(_665) + half3(_1203));
    half _1292 = clamp(dot(_649, half3(_1203)), half(0.0), half(1.0));
    half3 _1368 = cross(_649, _1341);
    half _1371 = clamp(dot(_649, _1341), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1388 = max(mix((half(2.0) * _1292) * _837, _1292 + _837, half(params.facet_alpha)), half(0.000244140625));
    half _1395 = _1142 / (fma(_1371, _1371, dot(_1368, _1368)) * (half(6433.98193359375) * _1388));
    half _1446 = half(1.0) - _837;
    half _1449 = _1446 * _1446;
    float4 _1473 = facet_environment.sample(facet_environmentSmplr, float3(_841), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1440 = mix(fma(half4(_902).xyz, mix(half4(_876).xxx, half4(_876).yyy, half3(float3(params.facet_f0))) * _895, min(((half3(float3(params.facet_f0)) * min(_1147 * (_1147 * (half(6.283185482025146484375) * _1140)), half(65504.0))) * _895) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_964) * half(_964)) / fast::max(_950, 9.9999997473787516355514526367188e-05)) * half(_983)) * half(_983)), float3(65504.0))) * _1044), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1395 * (_1395 * (half(6.283185482025146484375) * _1388)), half(65504.0))) * _895) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1212) * half(_1212)) / fast::max(_1198, 9.9999997473787516355514526367188e-05)) * half(_1231)) * half(_1231)), float3(65504.0))) * _1292), half3(float3(65504.0))), half4(_1473).xyz, half3(fma(half(0.959999978542327880859375), (_1449 * _1449) * _1446, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1440, half(1.0)));
    return out;
}

