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
    half3 _675 = normalize(half3(in.v_normal));
    float3 _691 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _881 = max(dot(_675, half3(_691)), half(9.9999997473787516355514526367188e-05));
    half3 _885 = reflect(-half3(_691), _675);
    float4 _920 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_881, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _939 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_920).y) - half(1.0)));
    float4 _949 = facet_environment.sample(facet_environmentSmplr, float3(_885), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _729 = half4(frame.lightDirection).xyz;
    half3 _1056 = normalize(half3(_691) + _729);
    half _1007 = clamp(dot(_675, _729), half(0.0), half(1.0));
    half4 _1125 = half4(cross(_675, _1056), half(params.facet_alpha) * clamp(dot(_675, _1056), half(0.0), half(1.0))) * half(64.0);
    half _1099 = half(4096.0) * half(params.facet_alpha);
    half _1102 = half(6.283185482025146484375) * max(mix((half(2.0) * _1007) * _881, _1007 + _881, half(params.facet_alpha)), half(0.000244140625));
    half _1104 = _1099 / (dot(_1125, _1125) * _1102);
    float3 _1169 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1172 = dot(_1169, _1169);
    float3 _1177 = _1169 * rsqrt(fast::max(_1172, 9.9999999392252902907785028219223e-09));
    float _1181 = _1172 * float(frame.punctualLights[0].positionFalloff.w);
    float _1186 = fast::clamp(fma(-_1181, _1181, 1.0), 0.0, 1.0);
    float _1205 = fast::clamp(fma(dot(-_1177, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1315 = normalize(half3(_691) + half3(_1177));
    half _1266 = clamp(dot(_675, half3(_1177)), half(0.0), half(1.0));
    half4 _1384 = half4(cross(_675, _1315), half(params.facet_alpha) * clamp(dot(_675, _1315), half(0.0), half(1.0))) * half(64.0);
    half _1361 = half(6.283185482025146484375) * max(mix((half(2.0) * _1266) * _881, _1266 + _881, half(params.facet_alpha)), half(0.000244140625));
    half _1363 = _1099 / (dot(_1384, _1384) * _1361);
    float3 _1428 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1431 = dot(_1428, _1428);
    float3 _1436 = _1428 * rsqrt(fast::max(_1431, 9.9999999392252902907785028219223e-09));
    float _1440 = _1431 * float(frame.punctualLights[1].positionFalloff.w);
    float _1445 = fast::clamp(fma(-_1440, _1440, 1.0), 0.0, 1.0);
    float _1464 = fast::clamp(fma(dot(-_1436, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1574 = normalize(half3(_691) + half3(_1436));
    half _1525 = clamp(dot(_675, half3(_1436)), half(0.0), half(1.0));
    half4 _1643 = half4(cross(_675, _1574), half(params.facet_alpha) * clamp(dot(_675, _1574), half(0.0), half(1.0))) * half(64.0);
    half _1620 = half(6.283185482025146484375) * max(mix((half(2.0) * _1525) * _881, _1525 + _881, half(params.facet_alpha)), half(0.000244140625));
    half _1622 = _1099 / (dot(_1643, _1643) * _1620);
    half3 _1651 = (fma(half4(_949).xyz, mix(half4(_920).xxx, half4(_920).yyy, half3(float3(params.facet_f0))) * _939, min(((half3(float3(params.facet_f0)) * min(_1104 * (_1104 * _1102), half(65504.0))) * _939) * (half4(frame.lightColor).xyz * _1007), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1363 * (_1363 * _1361), half(65504.0))) * _939) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1186) * half(_1186)) / fast::max(_1172, 9.9999997473787516355514526367188e-05)) * half(_1205)) * half(_1205)), float3(65504.0))) * _1266), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1622 * (_1622 * _1620), half(65504.0))) * _939) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1445) * half(_1445)) / fast::max(_1431, 9.9999997473787516355514526367188e-05)) * half(_1464)) * half(_1464)), float3(65504.0))) * _1525), half3(float3(65504.0)));
    half _1689 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1695 = half(1.0) - _881;
    half _1698 = _1695 * _1695;
    half _1714 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1724 = facet_environment.sample(facet_environmentSmplr, float3(_885), level(_1714 * (half(4.0) * (half(2.0) - _1714))));
    half3 _1684 = mix(_1651, half4(_1724).xyz, half3(fma(half(0.039999999105930328369140625), _1689, (half(0.959999978542327880859375) * _1689) * ((_1698 * _1698) * _1695))));
    out.fragColor = float4(half4(_1684, half(1.0)));
    return out;
}

