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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _585 = normalize(half3(in.v_normal));
    float3 _591 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _776 = max(dot(_585, half3(_591)), half(9.9999997473787516355514526367188e-05));
    float4 _781 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_776, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1446 = half4(_781);
    half _794 = _1446.z;
    half _796 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _794, half(1.0));
    half4 _1450 = half4(_781);
    half _801 = _1450.w;
    float4 _810 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_591), _585)), level(params.facet_sheenLod));
    float3 _880 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _883 = dot(_880, _880);
    float3 _888 = _880 * rsqrt(fast::max(_883, 9.9999999392252902907785028219223e-09));
    float _892 = _883 * float(frame.punctualLights[0].positionFalloff.w);
    float _897 = fast::clamp(fma(-_892, _892, 1.0), 0.0, 1.0);
    float _916 = fast::clamp(fma(dot(-_888, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _950 = dot(_585, half3(_888));
    half _952 = clamp(_950, half(0.0), half(1.0));
    half _964 = clamp(dot(_585, normalize(half3(_591) + half3(_888))), half(0.0), half(1.0));
    half _1033 = half(8192.0) * fma(half(-float(_952)), _776, _952 + _776);
    half _1037 = half(1.0) / (half(params.facet_alpha) * _1033);
    half _1044 = half(2048.0) * half(params.facet_alpha);
    half3 _997 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_950 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_952), half3(float3(0.0)), half3(float3(1.0)))) * _796) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1037, _1033, half(2.0)) * pow(max(fma(half(-float(_964)), _964, half(1.0)), half(0.0)), half(0.5) * (_1037 * _1033))) * half(0.15915493667125701904296875)) * (_952 * (_1037 * _1044))) * _801))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_897) * half(_897)) / fast::max(_883, 9.9999997473787516355514526367188e-05)) * half(_916)) * half(_916)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1108 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1111 = dot(_1108, _1108);
    float3 _1116 = _1108 * rsqrt(fast::max(_1111, 9.9999999392252902907785028219223e-09));
    float _1120 = _1111 * float(frame.punctualLights[1].positionFalloff.w);
    float _1125 = fast::clamp(fma(-_1120, _1120, 1.0), 0.0, 1.0);
    float _1144 = fast::clamp(fma(dot(-_1116, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1178 = dot(_585, half3(_1116));
    half _1180 = clamp(_1178, half(0.0), half(1.0));
    half _1192 = clamp(dot(_585, normalize(half3(_591) + half3(_1116))), half(0.0), half(1.0));
    half _1261 = half(8192.0) * fma(half(-float(_1180)), _776, _1180 + _776);
    half _1265 = half(1.0) / (half(params.facet_alpha) * _1261);
    half3 _1225 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1178 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1180), half3(float3(0.0)), half3(float3(1.0)))) * _796) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1265, _1261, half(2.0)) * pow(max(fma(half(-float(_1192)), _1192, half(1.0)), half(0.0)), half(0.5) * (_1265 * _1261))) * half(0.15915493667125701904296875)) * (_1180 * (_1265 * _1044))) * _801))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1125) * half(_1125)) / fast::max(_1111, 9.9999997473787516355514526367188e-05)) * half(_1144)) * half(_1144)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1300 = (fma(half4(_810).xyz, half3(float3(params.facet_sheenColor)) * _794, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _585.y)) + (half4(frame.sh[2]).xyz * _585.z)) + (half4(frame.sh[3]).xyz * _585.x), half3(float3(0.0)))) * _796) + _997) + _1225;
    out.fragColor = float4(half4(_1300, half(1.0)));
    return out;
}

