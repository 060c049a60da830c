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
    float4 _737 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_542, half3(_558)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _753 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_558), _542)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _798 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _801 = dot(_798, _798);
    float3 _806 = _798 * rsqrt(fast::max(_801, 9.9999999392252902907785028219223e-09));
    float _810 = _801 * float(frame.punctualLights[0].positionFalloff.w);
    float _815 = fast::clamp(fma(-_810, _810, 1.0), 0.0, 1.0);
    float _834 = fast::clamp(fma(dot(-_806, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _941 = normalize(half3(_558) + half3(_806));
    half _903 = clamp(dot(half3(_806), _941), half(0.0), half(1.0));
    half3 _969 = cross(_542, _941);
    half _972 = clamp(dot(_542, _941), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _997 = fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _998 = (half(12.56637096405029296875) * max(_903 * _903, half(0.1500000059604644775390625))) * _997;
    half _1003 = half(params.facet_alpha) / (fma(_972, _972, dot(_969, _969)) * _998);
    float3 _1050 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1053 = dot(_1050, _1050);
    float3 _1058 = _1050 * rsqrt(fast::max(_1053, 9.9999999392252902907785028219223e-09));
    float _1062 = _1053 * float(frame.punctualLights[1].positionFalloff.w);
    float _1067 = fast::clamp(fma(-_1062, _1062, 1.0), 0.0, 1.0);
    float _1086 = fast::clamp(fma(dot(-_1058, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1193 = normalize(half3(_558) + half3(_1058));
    half _1155 = clamp(dot(half3(_1058), _1193), half(0.0), half(1.0));
    half3 _1221 = cross(_542, _1193);
    half _1224 = clamp(dot(_542, _1193), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1250 = (half(12.56637096405029296875) * max(_1155 * _1155, half(0.1500000059604644775390625))) * _997;
    half _1255 = half(params.facet_alpha) / (fma(_1224, _1224, dot(_1221, _1221)) * _1250);
    half3 _1266 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_753).xyz * mix(half4(_737).xxx, half4(_737).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_1003 * _1003) * _998, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_815) * half(_815)) / fast::max(_801, 9.9999997473787516355514526367188e-05)) * half(_834)) * half(_834)), float3(65504.0))) * clamp(dot(_542, half3(_806)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min((_1255 * _1255) * _1250, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1067) * half(_1067)) / fast::max(_1053, 9.9999997473787516355514526367188e-05)) * half(_1086)) * half(_1086)), float3(65504.0))) * clamp(dot(_542, half3(_1058)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1266, half(1.0)));
    return out;
}

