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
    half3 _557 = normalize(half3(in.v_normal));
    float3 _573 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _721 = max(dot(_557, half3(_573)), half(9.9999997473787516355514526367188e-05));
    float4 _760 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_721, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _779 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_760).y) - half(1.0)));
    float4 _789 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_573), _557)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _834 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _837 = dot(_834, _834);
    float3 _842 = _834 * rsqrt(fast::max(_837, 9.9999999392252902907785028219223e-09));
    float _846 = _837 * float(frame.punctualLights[0].positionFalloff.w);
    float _851 = fast::clamp(fma(-_846, _846, 1.0), 0.0, 1.0);
    float _870 = fast::clamp(fma(dot(-_842, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _980 = normalize(half3(_573) + half3(_842));
    half _931 = clamp(dot(_557, half3(_842)), half(0.0), half(1.0));
    half3 _1007 = cross(_557, _980);
    half _1010 = clamp(dot(_557, _980), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1027 = max(mix((half(2.0) * _931) * _721, _931 + _721, half(params.facet_alpha)), half(0.000244140625));
    half _1029 = half(1024.0) * half(params.facet_alpha);
    half _1034 = _1029 / (fma(_1010, _1010, dot(_1007, _1007)) * (half(6433.98193359375) * _1027));
    float3 _1082 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1085 = dot(_1082, _1082);
    float3 _1090 = _1082 * rsqrt(fast::max(_1085, 9.9999999392252902907785028219223e-09));
    float _1094 = _1085 * float(frame.punctualLights[1].positionFalloff.w);
    float _1099 = fast::clamp(fma(-_1094, _1094, 1.0), 0.0, 1.0);
    float _1118 = fast::clamp(fma(dot(-_1090, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1228 = normalize(half3(_573) + half3(_1090));
    half _1179 = clamp(dot(_557, half3(_1090)), half(0.0), half(1.0));
    half3 _1255 = cross(_557, _1228);
    half _1258 = clamp(dot(_557, _1228), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1275 = max(mix((half(2.0) * _1179) * _721, _1179 + _721, half(params.facet_alpha)), half(0.000244140625));
    half _1282 = _1029 / (fma(_1258, _1258, dot(_1255, _1255)) * (half(6433.98193359375) * _1275));
    half3 _1294 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_789).xyz * (mix(half4(_760).xxx, half4(_760).yyy, half3(float3(params.facet_f0))) * _779)) + min(((half3(float3(params.facet_f0)) * min(_1034 * (_1034 * (half(6.283185482025146484375) * _1027)), half(65504.0))) * _779) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_851) * half(_851)) / fast::max(_837, 9.9999997473787516355514526367188e-05)) * half(_870)) * half(_870)), float3(65504.0))) * _931), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1282 * (_1282 * (half(6.283185482025146484375) * _1275)), half(65504.0))) * _779) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1099) * half(_1099)) / fast::max(_1085, 9.9999997473787516355514526367188e-05)) * half(_1118)) * half(_1118)), float3(65504.0))) * _1179), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1294, half(1.0)));
    return out;
}

