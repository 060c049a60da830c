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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _681 = normalize(half3(in.v_normal));
    float3 _687 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _904 = max(dot(_681, half3(_687)), half(9.9999997473787516355514526367188e-05));
    float4 _946 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_904, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _965 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_946).y) - half(1.0)));
    float4 _922 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_687), _681)), level(params.facet_environmentLod));
    half _1021 = clamp(dot(_681, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1080 = fast::normalize(_687 + frame.lightDirection.xyz);
    half _1120 = half(4096.0) * half(params.facet_alpha);
    half4 _1145 = half4(cross(_681, half3(_1080)), half(params.facet_alpha) * clamp(dot(_681, half3(_1080)), half(0.0), half(1.0))) * half(64.0);
    half _1126 = _1120 / dot(_1145, _1145);
    half _1170 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1080)), half(0.0), half(1.0));
    half _1173 = _1170 * _1170;
    half3 _1181 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1239 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1242 = dot(_1239, _1239);
    float3 _1247 = _1239 * rsqrt(fast::max(_1242, 9.9999999392252902907785028219223e-09));
    float _1251 = _1242 * float(frame.punctualLights[0].positionFalloff.w);
    float _1256 = fast::clamp(fma(-_1251, _1251, 1.0), 0.0, 1.0);
    float _1275 = fast::clamp(fma(dot(-_1247, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1335 = clamp(dot(_681, half3(_1247)), half(0.0), half(1.0));
    float3 _1394 = fast::normalize(_687 + _1247);
    half4 _1459 = half4(cross(_681, half3(_1394)), half(params.facet_alpha) * clamp(dot(_681, half3(_1394)), half(0.0), half(1.0))) * half(64.0);
    half _1440 = _1120 / dot(_1459, _1459);
    half _1484 = half(1.0) - clamp(dot(half3(_1247), half3(_1394)), half(0.0), half(1.0));
    half _1487 = _1484 * _1484;
    float3 _1553 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1556 = dot(_1553, _1553);
    float3 _1561 = _1553 * rsqrt(fast::max(_1556, 9.9999999392252902907785028219223e-09));
    float _1565 = _1556 * float(frame.punctualLights[1].positionFalloff.w);
    float _1570 = fast::clamp(fma(-_1565, _1565, 1.0), 0.0, 1.0);
    float _1589 = fast::clamp(fma(dot(-_1561, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1649 = clamp(dot(_681, half3(_1561)), half(0.0), half(1.0));
    float3 _1708 = fast::normalize(_687 + _1561);
    half4 _1773 = half4(cross(_681, half3(_1708)), half(params.facet_alpha) * clamp(dot(_681, half3(_1708)), half(0.0), half(1.0))) * half(64.0);
    half _1754 = _1120 / dot(_1773, _1773);
    half _1798 = half(1.0) - clamp(dot(half3(_1561), half3(_1708)), half(0.0), half(1.0));
    half _1801 = _1798 * _1798;
    half3 _1831 = (fma(half4(_922).xyz, mix(half4(_946).xxx, half4(_946).yyy, half3(float3(params.facet_f0))) * _965, min((((half3(float3(params.facet_f0)) + (_1181 * ((_1173 * _1173) * _1170))) * min(min((_1126 * _1126) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1021) * _904, _1021 + _904, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _965) * (half4(frame.lightColor).xyz * _1021), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1181 * ((_1487 * _1487) * _1484))) * min(min((_1440 * _1440) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1335) * _904, _1335 + _904, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _965) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1256) * half(_1256)) / fast::max(_1242, 9.9999997473787516355514526367188e-05)) * half(_1275)) * half(_1275)), float3(65504.0))) * _1335), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1181 * ((_1801 * _1801) * _1798))) * min(min((_1754 * _1754) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1649) * _904, _1649 + _904, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _965) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1570) * half(_1570)) / fast::max(_1556, 9.9999997473787516355514526367188e-05)) * half(_1589)) * half(_1589)), float3(65504.0))) * _1649), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1831, half(1.0)));
    return out;
}

