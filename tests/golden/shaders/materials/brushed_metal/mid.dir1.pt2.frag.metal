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
    half3 _583 = normalize(half3(in.v_normal));
    float3 _599 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _778 = max(dot(_583, half3(_599)), half(9.9999997473787516355514526367188e-05));
    float4 _817 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_778, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _836 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_817).y) - half(1.0)));
    float4 _843 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_599), _583)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _636 = half4(frame.lightDirection).xyz;
    half3 _950 = normalize(half3(_599) + _636);
    half _901 = clamp(dot(_583, _636), half(0.0), half(1.0));
    half4 _1019 = half4(cross(_583, _950), half(params.facet_alpha) * clamp(dot(_583, _950), half(0.0), half(1.0))) * half(64.0);
    half _993 = half(4096.0) * half(params.facet_alpha);
    half _996 = half(6.283185482025146484375) * max(mix((half(2.0) * _901) * _778, _901 + _778, half(params.facet_alpha)), half(0.000244140625));
    half _998 = _993 / (dot(_1019, _1019) * _996);
    float3 _1063 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1066 = dot(_1063, _1063);
    float3 _1071 = _1063 * rsqrt(fast::max(_1066, 9.9999999392252902907785028219223e-09));
    float _1075 = _1066 * float(frame.punctualLights[0].positionFalloff.w);
    float _1080 = fast::clamp(fma(-_1075, _1075, 1.0), 0.0, 1.0);
    float _1099 = fast::clamp(fma(dot(-_1071, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1209 = normalize(half3(_599) + half3(_1071));
    half _1160 = clamp(dot(_583, half3(_1071)), half(0.0), half(1.0));
    half4 _1278 = half4(cross(_583, _1209), half(params.facet_alpha) * clamp(dot(_583, _1209), half(0.0), half(1.0))) * half(64.0);
    half _1255 = half(6.283185482025146484375) * max(mix((half(2.0) * _1160) * _778, _1160 + _778, half(params.facet_alpha)), half(0.000244140625));
    half _1257 = _993 / (dot(_1278, _1278) * _1255);
    float3 _1322 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1325 = dot(_1322, _1322);
    float3 _1330 = _1322 * rsqrt(fast::max(_1325, 9.9999999392252902907785028219223e-09));
    float _1334 = _1325 * float(frame.punctualLights[1].positionFalloff.w);
    float _1339 = fast::clamp(fma(-_1334, _1334, 1.0), 0.0, 1.0);
    float _1358 = fast::clamp(fma(dot(-_1330, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1468 = normalize(half3(_599) + half3(_1330));
    half _1419 = clamp(dot(_583, half3(_1330)), half(0.0), half(1.0));
    half4 _1537 = half4(cross(_583, _1468), half(params.facet_alpha) * clamp(dot(_583, _1468), half(0.0), half(1.0))) * half(64.0);
    half _1514 = half(6.283185482025146484375) * max(mix((half(2.0) * _1419) * _778, _1419 + _778, half(params.facet_alpha)), half(0.000244140625));
    half _1516 = _993 / (dot(_1537, _1537) * _1514);
    half3 _1545 = (fma(half4(_843).xyz, mix(half4(_817).xxx, half4(_817).yyy, half3(float3(params.facet_f0))) * _836, min(((half3(float3(params.facet_f0)) * min(_998 * (_998 * _996), half(65504.0))) * _836) * (half4(frame.lightColor).xyz * _901), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1257 * (_1257 * _1255), half(65504.0))) * _836) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1080) * half(_1080)) / fast::max(_1066, 9.9999997473787516355514526367188e-05)) * half(_1099)) * half(_1099)), float3(65504.0))) * _1160), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1516 * (_1516 * _1514), half(65504.0))) * _836) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1339) * half(_1339)) / fast::max(_1325, 9.9999997473787516355514526367188e-05)) * half(_1358)) * half(_1358)), float3(65504.0))) * _1419), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1545, half(1.0)));
    return out;
}

