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
    half3 _505 = normalize(half3(in.v_normal));
    float3 _521 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _663 = max(dot(_505, half3(_521)), half(9.9999997473787516355514526367188e-05));
    float4 _668 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_663, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _722 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1265 = half4(_668);
    half _681 = _1265.z;
    half4 _1269 = half4(_668);
    half _688 = _1269.w;
    float4 _741 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_521), _505)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _778 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _781 = dot(_778, _778);
    float3 _786 = _778 * rsqrt(fast::max(_781, 9.9999999392252902907785028219223e-09));
    float _790 = _781 * float(frame.punctualLights[0].positionFalloff.w);
    float _795 = fast::clamp(fma(-_790, _790, 1.0), 0.0, 1.0);
    float _814 = fast::clamp(fma(dot(-_786, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _847 = clamp(dot(_505, half3(_786)), half(0.0), half(1.0));
    half _859 = clamp(dot(_505, normalize(half3(_521) + half3(_786))), half(0.0), half(1.0));
    half _904 = half(8192.0) * fma(half(-float(_847)), _663, _847 + _663);
    half _908 = half(1.0) / (half(params.facet_alpha) * _904);
    half _915 = half(2048.0) * half(params.facet_alpha);
    float3 _973 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _976 = dot(_973, _973);
    float3 _981 = _973 * rsqrt(fast::max(_976, 9.9999999392252902907785028219223e-09));
    float _985 = _976 * float(frame.punctualLights[1].positionFalloff.w);
    float _990 = fast::clamp(fma(-_985, _985, 1.0), 0.0, 1.0);
    float _1009 = fast::clamp(fma(dot(-_981, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1042 = clamp(dot(_505, half3(_981)), half(0.0), half(1.0));
    half _1054 = clamp(dot(_505, normalize(half3(_521) + half3(_981))), half(0.0), half(1.0));
    half _1099 = half(8192.0) * fma(half(-float(_1042)), _663, _1042 + _663);
    half _1103 = half(1.0) / (half(params.facet_alpha) * _1099);
    half3 _1132 = (fma(half4(_741).xyz, _722 * _681, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_722.x, max(_722.y, _722.z)))), _681, half(1.0))) + min((_722 * ((((fma(_908, _904, half(2.0)) * pow(max(fma(half(-float(_859)), _859, half(1.0)), half(0.0)), half(0.5) * (_908 * _904))) * half(0.15915493667125701904296875)) * (_847 * (_908 * _915))) * _688)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_795) * half(_795)) / fast::max(_781, 9.9999997473787516355514526367188e-05)) * half(_814)) * half(_814)), float3(65504.0))), half3(float3(65504.0)))) + min((_722 * ((((fma(_1103, _1099, half(2.0)) * pow(max(fma(half(-float(_1054)), _1054, half(1.0)), half(0.0)), half(0.5) * (_1103 * _1099))) * half(0.15915493667125701904296875)) * (_1042 * (_1103 * _915))) * _688)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_990) * half(_990)) / fast::max(_976, 9.9999997473787516355514526367188e-05)) * half(_1009)) * half(_1009)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1132, half(1.0)));
    return out;
}

