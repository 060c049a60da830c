#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
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
    half3 _568 = normalize(half3(in.v_normal));
    float3 _584 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _742 = max(dot(_568, half3(_584)), half(9.9999997473787516355514526367188e-05));
    float4 _781 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_742, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _800 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_781).y) - half(1.0)));
    float4 _810 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_584), _568)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _855 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _858 = dot(_855, _855);
    float3 _863 = _855 * rsqrt(fast::max(_858, 9.9999999392252902907785028219223e-09));
    float _867 = _858 * float(frame.punctualLights[0].positionFalloff.w);
    float _872 = fast::clamp(fma(-_867, _867, 1.0), 0.0, 1.0);
    float _891 = fast::clamp(fma(dot(-_863, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1001 = normalize(half3(_584) + half3(_863));
    half _952 = clamp(dot(_568, half3(_863)), half(0.0), half(1.0));
    half3 _1028 = cross(_568, _1001);
    half _1031 = clamp(dot(_568, _1001), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1048 = max(mix((half(2.0) * _952) * _742, _952 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _1050 = half(1024.0) * half(params.facet_alpha);
    half _1055 = _1050 / (fma(_1031, _1031, dot(_1028, _1028)) * (half(6433.98193359375) * _1048));
    float3 _1103 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1106 = dot(_1103, _1103);
    float3 _1111 = _1103 * rsqrt(fast::max(_1106, 9.9999999392252902907785028219223e-09));
    float _1115 = _1106 * float(frame.punctualLights[1].positionFalloff.w);
    float _1120 = fast::clamp(fma(-_1115, _1115, 1.0), 0.0, 1.0);
    float _1139 = fast::clamp(fma(dot(-_1111, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1249 = normalize(half3(_584) + half3(_1111));
    half _1200 = clamp(dot(_568, half3(_1111)), half(0.0), half(1.0));
    half3 _1276 = cross(_568, _1249);
    half _1279 = clamp(dot(_568, _1249), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1296 = max(mix((half(2.0) * _1200) * _742, _1200 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _1303 = _1050 / (fma(_1279, _1279, dot(_1276, _1276)) * (half(6433.98193359375) * _1296));
    half3 _1315 = fma(half4(_810).xyz, mix(half4(_781).xxx, half4(_781).yyy, half3(float3(params.facet_f0))) * _800, min(((half3(float3(params.facet_f0)) * min(_1055 * (_1055 * (half(6.283185482025146484375) * _1048)), half(65504.0))) * _800) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_872) * half(_872)) / fast::max(_858, 9.9999997473787516355514526367188e-05)) * half(_891)) * half(_891)), float3(65504.0))) * _952), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1303 * (_1303 * (half(6.283185482025146484375) * _1296)), half(65504.0))) * _800) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1120) * half(_1120)) / fast::max(_1106, 9.9999997473787516355514526367188e-05)) * half(_1139)) * half(_1139)), float3(65504.0))) * _1200), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1315, half(1.0)));
    return out;
}

