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
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    half3 _586 = normalize(half3(in.v_normal));
    float3 _602 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _760 = max(dot(_586, half3(_602)), half(9.9999997473787516355514526367188e-05));
    float4 _799 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_760, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _818 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_799).y) - half(1.0)));
    float4 _828 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_602), _586)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _873 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _876 = dot(_873, _873);
    float3 _881 = _873 * rsqrt(fast::max(_876, 9.9999999392252902907785028219223e-09));
    float _885 = _876 * float(frame.punctualLights[0].positionFalloff.w);
    float _890 = fast::clamp(fma(-_885, _885, 1.0), 0.0, 1.0);
    float _909 = fast::clamp(fma(dot(-_881, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1019 = normalize(half3(_602) + half3(_881));
    half _970 = clamp(dot(_586, half3(_881)), half(0.0), half(1.0));
    half4 _1088 = half4(cross(_586, _1019), half(params.facet_alpha) * clamp(dot(_586, _1019), half(0.0), half(1.0))) * half(64.0);
    half _1062 = half(4096.0) * half(params.facet_alpha);
    half _1065 = half(6.283185482025146484375) * max(mix((half(2.0) * _970) * _760, _970 + _760, half(params.facet_alpha)), half(0.000244140625));
    half _1067 = _1062 / (dot(_1088, _1088) * _1065);
    float3 _1132 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1135 = dot(_1132, _1132);
    float3 _1140 = _1132 * rsqrt(fast::max(_1135, 9.9999999392252902907785028219223e-09));
    float _1144 = _1135 * float(frame.punctualLights[1].positionFalloff.w);
    float _1149 = fast::clamp(fma(-_1144, _1144, 1.0), 0.0, 1.0);
    float _1168 = fast::clamp(fma(dot(-_1140, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1278 = normalize(half3(_602) + half3(_1140));
    half _1229 = clamp(dot(_586, half3(_1140)), half(0.0), half(1.0));
    half4 _1347 = half4(cross(_586, _1278), half(params.facet_alpha) * clamp(dot(_586, _1278), half(0.0), half(1.0))) * half(64.0);
    half _1324 = half(6.283185482025146484375) * max(mix((half(2.0) * _1229) * _760, _1229 + _760, half(params.facet_alpha)), half(0.000244140625));
    half _1326 = _1062 / (dot(_1347, _1347) * _1324);
    half3 _1355 = fma(half4(_828).xyz, mix(half4(_799).xxx, half4(_799).yyy, half3(float3(params.facet_f0))) * _818, min(((half3(float3(params.facet_f0)) * min(_1067 * (_1067 * _1065), half(65504.0))) * _818) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_890) * half(_890)) / fast::max(_876, 9.9999997473787516355514526367188e-05)) * half(_909)) * half(_909)), float3(65504.0))) * _970), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1326 * (_1326 * _1324), half(65504.0))) * _818) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1149) * half(_1149)) / fast::max(_1135, 9.9999997473787516355514526367188e-05)) * half(_1168)) * half(_1168)), float3(65504.0))) * _1229), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1355, half(1.0)));
    return out;
}

