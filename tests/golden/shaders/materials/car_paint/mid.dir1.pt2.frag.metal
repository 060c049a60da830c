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
    half3 _669 = normalize(half3(in.v_normal));
    float3 _685 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _875 = max(dot(_669, half3(_685)), half(9.9999997473787516355514526367188e-05));
    half3 _879 = reflect(-half3(_685), _669);
    float4 _914 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_875, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _933 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_914).y) - half(1.0)));
    float4 _940 = facet_environment.sample(facet_environmentSmplr, float3(_879), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _723 = half4(frame.lightDirection).xyz;
    half3 _1047 = normalize(half3(_685) + _723);
    half _998 = clamp(dot(_669, _723), half(0.0), half(1.0));
    half3 _1110 = cross(_669, _1047) * half(64.0);
    half _1113 = half(64.0) * half(params.facet_alpha);
    half _1114 = clamp(dot(_669, _1047), half(0.0), half(1.0)) * _1113;
    half _1090 = half(4096.0) * half(params.facet_alpha);
    half _1093 = half(6.283185482025146484375) * max(mix((half(2.0) * _998) * _875, _998 + _875, half(params.facet_alpha)), half(0.000244140625));
    half _1095 = _1090 / (fma(_1114, _1114, dot(_1110, _1110)) * _1093);
    float3 _1162 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1165 = dot(_1162, _1162);
    float3 _1170 = _1162 * rsqrt(fast::max(_1165, 9.9999999392252902907785028219223e-09));
    float _1174 = _1165 * float(frame.punctualLights[0].positionFalloff.w);
    float _1179 = fast::clamp(fma(-_1174, _1174, 1.0), 0.0, 1.0);
    float _1198 = fast::clamp(fma(dot(-_1170, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1308 = normalize(half3(_685) + half3(_1170));
    half _1259 = clamp(dot(_669, half3(_1170)), half(0.0), half(1.0));
    half3 _1371 = cross(_669, _1308) * half(64.0);
    half _1375 = clamp(dot(_669, _1308), half(0.0), half(1.0)) * _1113;
    half _1354 = half(6.283185482025146484375) * max(mix((half(2.0) * _1259) * _875, _1259 + _875, half(params.facet_alpha)), half(0.000244140625));
    half _1356 = _1090 / (fma(_1375, _1375, dot(_1371, _1371)) * _1354);
    float3 _1423 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1426 = dot(_1423, _1423);
    float3 _1431 = _1423 * rsqrt(fast::max(_1426, 9.9999999392252902907785028219223e-09));
    float _1435 = _1426 * float(frame.punctualLights[1].positionFalloff.w);
    float _1440 = fast::clamp(fma(-_1435, _1435, 1.0), 0.0, 1.0);
    float _1459 = fast::clamp(fma(dot(-_1431, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1569 = normalize(half3(_685) + half3(_1431));
    half _1520 = clamp(dot(_669, half3(_1431)), half(0.0), half(1.0));
    half3 _1632 = cross(_669, _1569) * half(64.0);
    half _1636 = clamp(dot(_669, _1569), half(0.0), half(1.0)) * _1113;
    half _1615 = half(6.283185482025146484375) * max(mix((half(2.0) * _1520) * _875, _1520 + _875, half(params.facet_alpha)), half(0.000244140625));
    half _1617 = _1090 / (fma(_1636, _1636, dot(_1632, _1632)) * _1615);
    half3 _1648 = (fma(half4(_940).xyz, mix(half4(_914).xxx, half4(_914).yyy, half3(float3(params.facet_f0))) * _933, min(((half3(float3(params.facet_f0)) * min(_1095 * (_1095 * _1093), half(65504.0))) * _933) * (half4(frame.lightColor).xyz * _998), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1356 * (_1356 * _1354), half(65504.0))) * _933) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1179) * half(_1179)) / fast::max(_1165, 9.9999997473787516355514526367188e-05)) * half(_1198)) * half(_1198)), float3(65504.0))) * _1259), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1617 * (_1617 * _1615), half(65504.0))) * _933) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1440) * half(_1440)) / fast::max(_1426, 9.9999997473787516355514526367188e-05)) * half(_1459)) * half(_1459)), float3(65504.0))) * _1520), half3(float3(65504.0)));
    half _1687 = half(1.0) - _875;
    half _1690 = _1687 * _1687;
    float4 _1714 = facet_environment.sample(facet_environmentSmplr, float3(_879), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1681 = mix(_1648, half4(_1714).xyz, half3(fma(half(0.959999978542327880859375), (_1690 * _1690) * _1687, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1681, half(1.0)));
    return out;
}

