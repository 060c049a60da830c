#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
    half3 _542 = normalize(half3(in.v_normal));
    float3 _558 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _758 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_542, half3(_558)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _774 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_558), _542)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _595 = half4(frame.lightDirection).xyz;
    half3 _878 = normalize(half3(_558) + _595);
    half _840 = clamp(dot(_595, _878), half(0.0), half(1.0));
    half3 _906 = cross(_542, _878);
    half _909 = clamp(dot(_542, _878), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _934 = fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _935 = (half(12.56637096405029296875) * max(_840 * _840, half(0.1500000059604644775390625))) * _934;
    half _940 = half(params.facet_alpha) / (fma(_909, _909, dot(_906, _906)) * _935);
    float3 _987 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _990 = dot(_987, _987);
    float3 _995 = _987 * rsqrt(fast::max(_990, 9.9999999392252902907785028219223e-09));
    float _999 = _990 * float(frame.punctualLights[0].positionFalloff.w);
    float _1004 = fast::clamp(fma(-_999, _999, 1.0), 0.0, 1.0);
    float _1023 = fast::clamp(fma(dot(-_995, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1130 = normalize(half3(_558) + half3(_995));
    half _1092 = clamp(dot(half3(_995), _1130), half(0.0), half(1.0));
    half3 _1158 = cross(_542, _1130);
    half _1161 = clamp(dot(_542, _1130), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1187 = (half(12.56637096405029296875) * max(_1092 * _1092, half(0.1500000059604644775390625))) * _934;
    half _1192 = half(params.facet_alpha) / (fma(_1161, _1161, dot(_1158, _1158)) * _1187);
    float3 _1239 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1242 = dot(_1239, _1239);
    float3 _1247 = _1239 * rsqrt(fast::max(_1242, 9.9999999392252902907785028219223e-09));
    float _1251 = _1242 * float(frame.punctualLights[1].positionFalloff.w);
    float _1256 = fast::clamp(fma(-_1251, _1251, 1.0), 0.0, 1.0);
    float _1275 = fast::clamp(fma(dot(-_1247, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1382 = normalize(half3(_558) + half3(_1247));
    half _1344 = clamp(dot(half3(_1247), _1382), half(0.0), half(1.0));
    half3 _1410 = cross(_542, _1382);
    half _1413 = clamp(dot(_542, _1382), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1439 = (half(12.56637096405029296875) * max(_1344 * _1344, half(0.1500000059604644775390625))) * _934;
    half _1444 = half(params.facet_alpha) / (fma(_1413, _1413, dot(_1410, _1410)) * _1439);
    half3 _1455 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_774).xyz * mix(half4(_758).xxx, half4(_758).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_940 * _940) * _935, half(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_542, _595), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min((_1192 * _1192) * _1187, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1004) * half(_1004)) / fast::max(_990, 9.9999997473787516355514526367188e-05)) * half(_1023)) * half(_1023)), float3(65504.0))) * clamp(dot(_542, half3(_995)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min((_1444 * _1444) * _1439, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1256) * half(_1256)) / fast::max(_1242, 9.9999997473787516355514526367188e-05)) * half(_1275)) * half(_1275)), float3(65504.0))) * clamp(dot(_542, half3(_1247)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1455, half(1.0)));
    return out;
}

