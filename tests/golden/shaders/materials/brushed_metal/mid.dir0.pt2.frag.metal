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
    half3 _570 = normalize(half3(in.v_normal));
    float3 _586 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _744 = max(dot(_570, half3(_586)), half(9.9999997473787516355514526367188e-05));
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_744, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _802 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_783).y) - half(1.0)));
    float4 _814 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_586), _570)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _859 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _862 = dot(_859, _859);
    float3 _867 = _859 * rsqrt(fast::max(_862, 9.9999999392252902907785028219223e-09));
    float _871 = _862 * float(frame.punctualLights[0].positionFalloff.w);
    float _876 = fast::clamp(fma(-_871, _871, 1.0), 0.0, 1.0);
    float _895 = fast::clamp(fma(dot(-_867, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1005 = normalize(half3(_586) + half3(_867));
    half _956 = clamp(dot(_570, half3(_867)), half(0.0), half(1.0));
    half3 _1032 = cross(_570, _1005);
    half _1035 = clamp(dot(_570, _1005), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1052 = max(mix((half(2.0) * _956) * _744, _956 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1054 = half(1024.0) * half(params.facet_alpha);
    half _1059 = _1054 / (fma(_1035, _1035, dot(_1032, _1032)) * (half(6433.98193359375) * _1052));
    float3 _1107 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1110 = dot(_1107, _1107);
    float3 _1115 = _1107 * rsqrt(fast::max(_1110, 9.9999999392252902907785028219223e-09));
    float _1119 = _1110 * float(frame.punctualLights[1].positionFalloff.w);
    float _1124 = fast::clamp(fma(-_1119, _1119, 1.0), 0.0, 1.0);
    float _1143 = fast::clamp(fma(dot(-_1115, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1253 = normalize(half3(_586) + half3(_1115));
    half _1204 = clamp(dot(_570, half3(_1115)), half(0.0), half(1.0));
    half3 _1280 = cross(_570, _1253);
    half _1283 = clamp(dot(_570, _1253), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1300 = max(mix((half(2.0) * _1204) * _744, _1204 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1307 = _1054 / (fma(_1283, _1283, dot(_1280, _1280)) * (half(6433.98193359375) * _1300));
    half3 _1319 = fma(half4(_814).xyz, mix(half4(_783).xxx, half4(_783).yyy, half3(float3(params.facet_f0))) * _802, min(((half3(float3(params.facet_f0)) * min(_1059 * (_1059 * (half(6.283185482025146484375) * _1052)), half(65504.0))) * _802) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_876) * half(_876)) / fast::max(_862, 9.9999997473787516355514526367188e-05)) * half(_895)) * half(_895)), float3(65504.0))) * _956), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1307 * (_1307 * (half(6.283185482025146484375) * _1300)), half(65504.0))) * _802) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1124) * half(_1124)) / fast::max(_1110, 9.9999997473787516355514526367188e-05)) * half(_1143)) * half(_1143)), float3(65504.0))) * _1204), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1319, half(1.0)));
    return out;
}

