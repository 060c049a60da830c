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
    half3 _567 = normalize(half3(in.v_normal));
    float3 _583 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _750 = max(dot(_567, half3(_583)), half(9.9999997473787516355514526367188e-05));
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_750, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _799 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_583), _567)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _904 = fast::normalize(_583 + frame.lightDirection.xyz);
    half _857 = clamp(dot(_567, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _944 = cross(_567, half3(_904));
    half _947 = clamp(dot(_567, half3(_904)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _956 = half(params.facet_alpha) / fma(_947, _947, dot(_944, _944));
    half _984 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_904)), half(0.0), half(1.0));
    half _987 = _984 * _984;
    half3 _995 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1039 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1042 = dot(_1039, _1039);
    float3 _1047 = _1039 * rsqrt(fast::max(_1042, 9.9999999392252902907785028219223e-09));
    float _1051 = _1042 * float(frame.punctualLights[0].positionFalloff.w);
    float _1056 = fast::clamp(fma(-_1051, _1051, 1.0), 0.0, 1.0);
    float _1075 = fast::clamp(fma(dot(-_1047, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1183 = fast::normalize(_583 + _1047);
    half _1136 = clamp(dot(_567, half3(_1047)), half(0.0), half(1.0));
    half3 _1223 = cross(_567, half3(_1183));
    half _1226 = clamp(dot(_567, half3(_1183)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1235 = half(params.facet_alpha) / fma(_1226, _1226, dot(_1223, _1223));
    half _1263 = half(1.0) - clamp(dot(half3(_1047), half3(_1183)), half(0.0), half(1.0));
    half _1266 = _1263 * _1263;
    float3 _1318 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1321 = dot(_1318, _1318);
    float3 _1326 = _1318 * rsqrt(fast::max(_1321, 9.9999999392252902907785028219223e-09));
    float _1330 = _1321 * float(frame.punctualLights[1].positionFalloff.w);
    float _1335 = fast::clamp(fma(-_1330, _1330, 1.0), 0.0, 1.0);
    float _1354 = fast::clamp(fma(dot(-_1326, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1462 = fast::normalize(_583 + _1326);
    half _1415 = clamp(dot(_567, half3(_1326)), half(0.0), half(1.0));
    half3 _1502 = cross(_567, half3(_1462));
    half _1505 = clamp(dot(_567, half3(_1462)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1514 = half(params.facet_alpha) / fma(_1505, _1505, dot(_1502, _1502));
    half _1542 = half(1.0) - clamp(dot(half3(_1326), half3(_1462)), half(0.0), half(1.0));
    half _1545 = _1542 * _1542;
    half3 _1561 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_799).xyz * mix(half4(_783).xxx, half4(_783).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + (_995 * ((_987 * _987) * _984))) * min(min((_956 * _956) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _857) * _750, _857 + _750, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _857), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_995 * ((_1266 * _1266) * _1263))) * min(min((_1235 * _1235) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1136) * _750, _1136 + _750, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1056) * half(_1056)) / fast::max(_1042, 9.9999997473787516355514526367188e-05)) * half(_1075)) * half(_1075)), float3(65504.0))) * _1136), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_995 * ((_1545 * _1545) * _1542))) * min(min((_1514 * _1514) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1415) * _750, _1415 + _750, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1335) * half(_1335)) / fast::max(_1321, 9.9999997473787516355514526367188e-05)) * half(_1354)) * half(_1354)), float3(65504.0))) * _1415), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1561, half(1.0)));
    return out;
}

