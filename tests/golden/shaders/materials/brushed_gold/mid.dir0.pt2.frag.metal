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
    half3 _696 = normalize(half3(in.v_normal));
    float3 _702 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _900 = max(dot(_696, half3(_702)), half(9.9999997473787516355514526367188e-05));
    float4 _939 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_900, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _958 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_939).y) - half(1.0)));
    float4 _968 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_702), _696)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1013 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1016 = dot(_1013, _1013);
    float3 _1021 = _1013 * rsqrt(fast::max(_1016, 9.9999999392252902907785028219223e-09));
    float _1025 = _1016 * float(frame.punctualLights[0].positionFalloff.w);
    float _1030 = fast::clamp(fma(-_1025, _1025, 1.0), 0.0, 1.0);
    float _1049 = fast::clamp(fma(dot(-_1021, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1168 = fast::normalize(_702 + _1021);
    half _1112 = clamp(dot(_696, half3(_1021)), half(0.0), half(1.0));
    half _1208 = half(4096.0) * half(params.facet_alpha);
    half4 _1233 = half4(cross(_696, half3(_1168)), half(params.facet_alpha) * clamp(dot(_696, half3(_1168)), half(0.0), half(1.0))) * half(64.0);
    half _1214 = _1208 / dot(_1233, _1233);
    half _1258 = half(1.0) - clamp(dot(half3(_1021), half3(_1168)), half(0.0), half(1.0));
    half _1261 = _1258 * _1258;
    half3 _1269 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1327 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1330 = dot(_1327, _1327);
    float3 _1335 = _1327 * rsqrt(fast::max(_1330, 9.9999999392252902907785028219223e-09));
    float _1339 = _1330 * float(frame.punctualLights[1].positionFalloff.w);
    float _1344 = fast::clamp(fma(-_1339, _1339, 1.0), 0.0, 1.0);
    float _1363 = fast::clamp(fma(dot(-_1335, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1482 = fast::normalize(_702 + _1335);
    half _1426 = clamp(dot(_696, half3(_1335)), half(0.0), half(1.0));
    half4 _1547 = half4(cross(_696, half3(_1482)), half(params.facet_alpha) * clamp(dot(_696, half3(_1482)), half(0.0), half(1.0))) * half(64.0);
    half _1528 = _1208 / dot(_1547, _1547);
    half _1572 = half(1.0) - clamp(dot(half3(_1335), half3(_1482)), half(0.0), half(1.0));
    half _1575 = _1572 * _1572;
    half3 _1605 = fma(half4(_968).xyz, mix(half4(_939).xxx, half4(_939).yyy, half3(float3(params.facet_f0))) * _958, min((((half3(float3(params.facet_f0)) + (_1269 * ((_1261 * _1261) * _1258))) * min(min((_1214 * _1214) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1112) * _900, _1112 + _900, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _958) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1030) * half(_1030)) / fast::max(_1016, 9.9999997473787516355514526367188e-05)) * half(_1049)) * half(_1049)), float3(65504.0))) * _1112), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1269 * ((_1575 * _1575) * _1572))) * min(min((_1528 * _1528) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1426) * _900, _1426 + _900, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _958) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1344) * half(_1344)) / fast::max(_1330, 9.9999997473787516355514526367188e-05)) * half(_1363)) * half(_1363)), float3(65504.0))) * _1426), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1605, half(1.0)));
    return out;
}

