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
    half3 _502 = normalize(half3(in.v_normal));
    float3 _518 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _662 = max(dot(_502, half3(_518)), half(9.9999997473787516355514526367188e-05));
    float4 _667 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_662, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _721 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1261 = half4(_667);
    half _680 = _1261.z;
    half4 _1265 = half4(_667);
    half _687 = _1265.w;
    float4 _737 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_518), _502)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _774 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _777 = dot(_774, _774);
    float3 _782 = _774 * rsqrt(fast::max(_777, 9.9999999392252902907785028219223e-09));
    float _786 = _777 * float(frame.punctualLights[0].positionFalloff.w);
    float _791 = fast::clamp(fma(-_786, _786, 1.0), 0.0, 1.0);
    float _810 = fast::clamp(fma(dot(-_782, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _843 = clamp(dot(_502, half3(_782)), half(0.0), half(1.0));
    half _855 = clamp(dot(_502, normalize(half3(_518) + half3(_782))), half(0.0), half(1.0));
    half _900 = half(8192.0) * fma(half(-float(_843)), _662, _843 + _662);
    half _904 = half(1.0) / (half(params.facet_alpha) * _900);
    half _911 = half(2048.0) * half(params.facet_alpha);
    float3 _969 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _972 = dot(_969, _969);
    float3 _977 = _969 * rsqrt(fast::max(_972, 9.9999999392252902907785028219223e-09));
    float _981 = _972 * float(frame.punctualLights[1].positionFalloff.w);
    float _986 = fast::clamp(fma(-_981, _981, 1.0), 0.0, 1.0);
    float _1005 = fast::clamp(fma(dot(-_977, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1038 = clamp(dot(_502, half3(_977)), half(0.0), half(1.0));
    half _1050 = clamp(dot(_502, normalize(half3(_518) + half3(_977))), half(0.0), half(1.0));
    half _1095 = half(8192.0) * fma(half(-float(_1038)), _662, _1038 + _662);
    half _1099 = half(1.0) / (half(params.facet_alpha) * _1095);
    half3 _1128 = (fma(half4(_737).xyz, _721 * _680, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_721.x, max(_721.y, _721.z)))), _680, half(1.0))) + min((_721 * ((((fma(_904, _900, half(2.0)) * pow(max(fma(half(-float(_855)), _855, half(1.0)), half(0.0)), half(0.5) * (_904 * _900))) * half(0.15915493667125701904296875)) * (_843 * (_904 * _911))) * _687)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_791) * half(_791)) / fast::max(_777, 9.9999997473787516355514526367188e-05)) * half(_810)) * half(_810)), float3(65504.0))), half3(float3(65504.0)))) + min((_721 * ((((fma(_1099, _1095, half(2.0)) * pow(max(fma(half(-float(_1050)), _1050, half(1.0)), half(0.0)), half(0.5) * (_1099 * _1095))) * half(0.15915493667125701904296875)) * (_1038 * (_1099 * _911))) * _687)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_986) * half(_986)) / fast::max(_972, 9.9999997473787516355514526367188e-05)) * half(_1005)) * half(_1005)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1128, half(1.0)));
    return out;
}

