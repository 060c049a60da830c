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
    half3 _554 = normalize(half3(in.v_normal));
    float3 _570 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _721 = max(dot(_554, half3(_570)), half(9.9999997473787516355514526367188e-05));
    float4 _760 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_721, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _779 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_760).y) - half(1.0)));
    float4 _786 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_570), _554)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _831 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _834 = dot(_831, _831);
    float3 _839 = _831 * rsqrt(fast::max(_834, 9.9999999392252902907785028219223e-09));
    float _843 = _834 * float(frame.punctualLights[0].positionFalloff.w);
    float _848 = fast::clamp(fma(-_843, _843, 1.0), 0.0, 1.0);
    float _867 = fast::clamp(fma(dot(-_839, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _977 = normalize(half3(_570) + half3(_839));
    half _928 = clamp(dot(_554, half3(_839)), half(0.0), half(1.0));
    half3 _1004 = cross(_554, _977);
    half _1007 = clamp(dot(_554, _977), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1024 = max(mix((half(2.0) * _928) * _721, _928 + _721, half(params.facet_alpha)), half(0.000244140625));
    half _1026 = half(1024.0) * half(params.facet_alpha);
    half _1031 = _1026 / (fma(_1007, _1007, dot(_1004, _1004)) * (half(6433.98193359375) * _1024));
    float3 _1079 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1082 = dot(_1079, _1079);
    float3 _1087 = _1079 * rsqrt(fast::max(_1082, 9.9999999392252902907785028219223e-09));
    float _1091 = _1082 * float(frame.punctualLights[1].positionFalloff.w);
    float _1096 = fast::clamp(fma(-_1091, _1091, 1.0), 0.0, 1.0);
    float _1115 = fast::clamp(fma(dot(-_1087, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1225 = normalize(half3(_570) + half3(_1087));
    half _1176 = clamp(dot(_554, half3(_1087)), half(0.0), half(1.0));
    half3 _1252 = cross(_554, _1225);
    half _1255 = clamp(dot(_554, _1225), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1272 = max(mix((half(2.0) * _1176) * _721, _1176 + _721, half(params.facet_alpha)), half(0.000244140625));
    half _1279 = _1026 / (fma(_1255, _1255, dot(_1252, _1252)) * (half(6433.98193359375) * _1272));
    half3 _1291 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_786).xyz * (mix(half4(_760).xxx, half4(_760).yyy, half3(float3(params.facet_f0))) * _779)) + min(((half3(float3(params.facet_f0)) * min(_1031 * (_1031 * (half(6.283185482025146484375) * _1024)), half(65504.0))) * _779) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_848) * half(_848)) / fast::max(_834, 9.9999997473787516355514526367188e-05)) * half(_867)) * half(_867)), float3(65504.0))) * _928), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1279 * (_1279 * (half(6.283185482025146484375) * _1272)), half(65504.0))) * _779) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1096) * half(_1096)) / fast::max(_1082, 9.9999997473787516355514526367188e-05)) * half(_1115)) * half(_1115)), float3(65504.0))) * _1176), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1291, half(1.0)));
    return out;
}

