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
    half3 _574 = normalize(half3(in.v_normal));
    float3 _590 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _738 = max(dot(_574, half3(_590)), half(9.9999997473787516355514526367188e-05));
    float4 _777 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_738, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _796 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_777).y) - half(1.0)));
    float4 _803 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_590), _574)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _848 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _851 = dot(_848, _848);
    float3 _856 = _848 * rsqrt(fast::max(_851, 9.9999999392252902907785028219223e-09));
    float _860 = _851 * float(frame.punctualLights[0].positionFalloff.w);
    float _865 = fast::clamp(fma(-_860, _860, 1.0), 0.0, 1.0);
    float _884 = fast::clamp(fma(dot(-_856, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _994 = normalize(half3(_590) + half3(_856));
    half _945 = clamp(dot(_574, half3(_856)), half(0.0), half(1.0));
    half3 _1057 = cross(_574, _994) * half(64.0);
    half _1060 = half(64.0) * half(params.facet_alpha);
    half _1061 = clamp(dot(_574, _994), half(0.0), half(1.0)) * _1060;
    half _1037 = half(4096.0) * half(params.facet_alpha);
    half _1040 = half(6.283185482025146484375) * max(mix((half(2.0) * _945) * _738, _945 + _738, half(params.facet_alpha)), half(0.000244140625));
    half _1042 = _1037 / (fma(_1061, _1061, dot(_1057, _1057)) * _1040);
    float3 _1109 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1112 = dot(_1109, _1109);
    float3 _1117 = _1109 * rsqrt(fast::max(_1112, 9.9999999392252902907785028219223e-09));
    float _1121 = _1112 * float(frame.punctualLights[1].positionFalloff.w);
    float _1126 = fast::clamp(fma(-_1121, _1121, 1.0), 0.0, 1.0);
    float _1145 = fast::clamp(fma(dot(-_1117, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1255 = normalize(half3(_590) + half3(_1117));
    half _1206 = clamp(dot(_574, half3(_1117)), half(0.0), half(1.0));
    half3 _1318 = cross(_574, _1255) * half(64.0);
    half _1322 = clamp(dot(_574, _1255), half(0.0), half(1.0)) * _1060;
    half _1301 = half(6.283185482025146484375) * max(mix((half(2.0) * _1206) * _738, _1206 + _738, half(params.facet_alpha)), half(0.000244140625));
    half _1303 = _1037 / (fma(_1322, _1322, dot(_1318, _1318)) * _1301);
    half3 _1334 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_803).xyz * (mix(half4(_777).xxx, half4(_777).yyy, half3(float3(params.facet_f0))) * _796)) + min(((half3(float3(params.facet_f0)) * min(_1042 * (_1042 * _1040), half(65504.0))) * _796) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_865) * half(_865)) / fast::max(_851, 9.9999997473787516355514526367188e-05)) * half(_884)) * half(_884)), float3(65504.0))) * _945), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1303 * (_1303 * _1301), half(65504.0))) * _796) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1126) * half(_1126)) / fast::max(_1112, 9.9999997473787516355514526367188e-05)) * half(_1145)) * half(_1145)), float3(65504.0))) * _1206), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1334, half(1.0)));
    return out;
}

