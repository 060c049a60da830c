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
    half _854 = max(dot(_669, half3(_685)), half(9.9999997473787516355514526367188e-05));
    half3 _858 = reflect(-half3(_685), _669);
    float4 _893 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_854, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _912 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_893).y) - half(1.0)));
    float4 _919 = facet_environment.sample(facet_environmentSmplr, float3(_858), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _964 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _967 = dot(_964, _964);
    float3 _972 = _964 * rsqrt(fast::max(_967, 9.9999999392252902907785028219223e-09));
    float _976 = _967 * float(frame.punctualLights[0].positionFalloff.w);
    float _981 = fast::clamp(fma(-_976, _976, 1.0), 0.0, 1.0);
    float _1000 = fast::clamp(fma(dot(-_972, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1110 = normalize(half3(_685) + half3(_972));
    half _1061 = clamp(dot(_669, half3(_972)), half(0.0), half(1.0));
    half3 _1173 = cross(_669, _1110) * half(64.0);
    half _1176 = half(64.0) * half(params.facet_alpha);
    half _1177 = clamp(dot(_669, _1110), half(0.0), half(1.0)) * _1176;
    half _1153 = half(4096.0) * half(params.facet_alpha);
    half _1156 = half(6.283185482025146484375) * max(mix((half(2.0) * _1061) * _854, _1061 + _854, half(params.facet_alpha)), half(0.000244140625));
    half _1158 = _1153 / (fma(_1177, _1177, dot(_1173, _1173)) * _1156);
    float3 _1225 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1228 = dot(_1225, _1225);
    float3 _1233 = _1225 * rsqrt(fast::max(_1228, 9.9999999392252902907785028219223e-09));
    float _1237 = _1228 * float(frame.punctualLights[1].positionFalloff.w);
    float _1242 = fast::clamp(fma(-_1237, _1237, 1.0), 0.0, 1.0);
    float _1261 = fast::clamp(fma(dot(-_1233, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1371 = normalize(half3(_685) + half3(_1233));
    half _1322 = clamp(dot(_669, half3(_1233)), half(0.0), half(1.0));
    half3 _1434 = cross(_669, _1371) * half(64.0);
    half _1438 = clamp(dot(_669, _1371), half(0.0), half(1.0)) * _1176;
    half _1417 = half(6.283185482025146484375) * max(mix((half(2.0) * _1322) * _854, _1322 + _854, half(params.facet_alpha)), half(0.000244140625));
    half _1419 = _1153 / (fma(_1438, _1438, dot(_1434, _1434)) * _1417);
    half _1489 = half(1.0) - _854;
    half _1492 = _1489 * _1489;
    float4 _1516 = facet_environment.sample(facet_environmentSmplr, float3(_858), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1483 = mix(fma(half4(_919).xyz, mix(half4(_893).xxx, half4(_893).yyy, half3(float3(params.facet_f0))) * _912, min(((half3(float3(params.facet_f0)) * min(_1158 * (_1158 * _1156), half(65504.0))) * _912) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_981) * half(_981)) / fast::max(_967, 9.9999997473787516355514526367188e-05)) * half(_1000)) * half(_1000)), float3(65504.0))) * _1061), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1419 * (_1419 * _1417), half(65504.0))) * _912) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1242) * half(_1242)) / fast::max(_1228, 9.9999997473787516355514526367188e-05)) * half(_1261)) * half(_1261)), float3(65504.0))) * _1322), half3(float3(65504.0))), half4(_1516).xyz, half3(fma(half(0.959999978542327880859375), (_1492 * _1492) * _1489, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1483, half(1.0)));
    return out;
}

