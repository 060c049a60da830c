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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _548 = normalize(half3(in.v_normal));
    float3 _564 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _703 = facet_irradiance.sample(facet_irradianceSmplr, float3(_548), level(0.0));
    half _743 = max(dot(_548, half3(_564)), half(9.9999997473787516355514526367188e-05));
    float4 _748 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_743, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1566 = half4(_748);
    half _761 = _1566.z;
    half _763 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _761, half(1.0));
    half4 _1570 = half4(_748);
    half _768 = _1570.w;
    float4 _777 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_564), _548)), level(params.facet_sheenLod));
    half3 _596 = half4(frame.lightDirection).xyz;
    half _833 = dot(_548, _596);
    half _835 = clamp(_833, half(0.0), half(1.0));
    half _847 = clamp(dot(_548, normalize(half3(_564) + _596)), half(0.0), half(1.0));
    half _916 = half(8192.0) * fma(half(-float(_835)), _743, _835 + _743);
    half _920 = half(1.0) / (half(params.facet_alpha) * _916);
    half _927 = half(2048.0) * half(params.facet_alpha);
    float3 _991 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _994 = dot(_991, _991);
    float3 _999 = _991 * rsqrt(fast::max(_994, 9.9999999392252902907785028219223e-09));
    float _1003 = _994 * float(frame.punctualLights[0].positionFalloff.w);
    float _1008 = fast::clamp(fma(-_1003, _1003, 1.0), 0.0, 1.0);
    float _1027 = fast::clamp(fma(dot(-_999, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1061 = dot(_548, half3(_999));
    half _1063 = clamp(_1061, half(0.0), half(1.0));
    half _1075 = clamp(dot(_548, normalize(half3(_564) + half3(_999))), half(0.0), half(1.0));
    half _1144 = half(8192.0) * fma(half(-float(_1063)), _743, _1063 + _743);
    half _1148 = half(1.0) / (half(params.facet_alpha) * _1144);
    half3 _1108 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1061 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1063), half3(float3(0.0)), half3(float3(1.0)))) * _763) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1148, _1144, half(2.0)) * pow(max(fma(half(-float(_1075)), _1075, half(1.0)), half(0.0)), half(0.5) * (_1148 * _1144))) * half(0.15915493667125701904296875)) * (_1063 * (_1148 * _927))) * _768))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1008) * half(_1008)) / fast::max(_994, 9.9999997473787516355514526367188e-05)) * half(_1027)) * half(_1027)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1183 = (fma(half4(_777).xyz, half3(float3(params.facet_sheenColor)) * _761, (half3(float3(params.facet_diffuseColor)) * half4(_703).xyz) * _763) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_833 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_835), half3(float3(0.0)), half3(float3(1.0)))) * _763) + (half3(float3(params.facet_sheenColor)) * ((((fma(_920, _916, half(2.0)) * pow(max(fma(half(-float(_847)), _847, half(1.0)), half(0.0)), half(0.5) * (_920 * _916))) * half(0.15915493667125701904296875)) * (_835 * (_920 * _927))) * _768))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1108;
    float3 _1219 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1222 = dot(_1219, _1219);
    float3 _1227 = _1219 * rsqrt(fast::max(_1222, 9.9999999392252902907785028219223e-09));
    float _1231 = _1222 * float(frame.punctualLights[1].positionFalloff.w);
    float _1236 = fast::clamp(fma(-_1231, _1231, 1.0), 0.0, 1.0);
    float _1255 = fast::clamp(fma(dot(-_1227, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1289 = dot(_548, half3(_1227));
    half _1291 = clamp(_1289, half(0.0), half(1.0));
    half _1303 = clamp(dot(_548, normalize(half3(_564) + half3(_1227))), half(0.0), half(1.0));
    half _1372 = half(8192.0) * fma(half(-float(_1291)), _743, _1291 + _743);
    half _1376 = half(1.0) / (half(params.facet_alpha) * _1372);
    half3 _1336 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1289 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1291), half3(float3(0.0)), half3(float3(1.0)))) * _763) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1376, _1372, half(2.0)) * pow(max(fma(half(-float(_1303)), _1303, half(1.0)), half(0.0)), half(0.5) * (_1376 * _1372))) * half(0.15915493667125701904296875)) * (_1291 * (_1376 * _927))) * _768))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1236) * half(_1236)) / fast::max(_1222, 9.9999997473787516355514526367188e-05)) * half(_1255)) * half(_1255)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1183 + _1336, half(1.0)));
    return out;
}

