#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    half3 _560 = normalize(half3(in.v_normal));
    float3 _576 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _729 = max(dot(_560, half3(_576)), half(9.9999997473787516355514526367188e-05));
    float4 _768 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_729, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _787 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_768).y) - half(1.0)));
    float4 _797 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_576), _560)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _842 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _845 = dot(_842, _842);
    float3 _850 = _842 * rsqrt(fast::max(_845, 9.9999999392252902907785028219223e-09));
    float _854 = _845 * float(frame.punctualLights[0].positionFalloff.w);
    float _859 = fast::clamp(fma(-_854, _854, 1.0), 0.0, 1.0);
    float _878 = fast::clamp(fma(dot(-_850, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _988 = normalize(half3(_576) + half3(_850));
    half _939 = clamp(dot(_560, half3(_850)), half(0.0), half(1.0));
    half3 _1015 = cross(_560, _988);
    half _1018 = clamp(dot(_560, _988), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1035 = max(mix((half(2.0) * _939) * _729, _939 + _729, half(params.facet_alpha)), half(0.000244140625));
    half _1037 = half(1024.0) * half(params.facet_alpha);
    half _1042 = _1037 / (fma(_1018, _1018, dot(_1015, _1015)) * (half(6433.98193359375) * _1035));
    float3 _1090 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1093 = dot(_1090, _1090);
    float3 _1098 = _1090 * rsqrt(fast::max(_1093, 9.9999999392252902907785028219223e-09));
    float _1102 = _1093 * float(frame.punctualLights[1].positionFalloff.w);
    float _1107 = fast::clamp(fma(-_1102, _1102, 1.0), 0.0, 1.0);
    float _1126 = fast::clamp(fma(dot(-_1098, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1236 = normalize(half3(_576) + half3(_1098));
    half _1187 = clamp(dot(_560, half3(_1098)), half(0.0), half(1.0));
    half3 _1263 = cross(_560, _1236);
    half _1266 = clamp(dot(_560, _1236), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1283 = max(mix((half(2.0) * _1187) * _729, _1187 + _729, half(params.facet_alpha)), half(0.000244140625));
    half _1290 = _1037 / (fma(_1266, _1266, dot(_1263, _1263)) * (half(6433.98193359375) * _1283));
    half3 _1302 = fma(half4(_797).xyz, mix(half4(_768).xxx, half4(_768).yyy, half3(float3(params.facet_f0))) * _787, min(((half3(float3(params.facet_f0)) * min(_1042 * (_1042 * (half(6.283185482025146484375) * _1035)), half(65504.0))) * _787) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_859) * half(_859)) / fast::max(_845, 9.9999997473787516355514526367188e-05)) * half(_878)) * half(_878)), float3(65504.0))) * _939), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1290 * (_1290 * (half(6.283185482025146484375) * _1283)), half(65504.0))) * _787) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1107) * half(_1107)) / fast::max(_1093, 9.9999997473787516355514526367188e-05)) * half(_1126)) * half(_1126)), float3(65504.0))) * _1187), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1302, half(1.0)));
    return out;
}

