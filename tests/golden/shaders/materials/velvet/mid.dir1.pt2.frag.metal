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
    half _685 = max(dot(_505, half3(_521)), half(9.9999997473787516355514526367188e-05));
    float4 _690 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_685, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _744 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1400 = half4(_690);
    half _703 = _1400.z;
    half4 _1404 = half4(_690);
    half _710 = _1404.w;
    float4 _763 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_521), _505)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _556 = half4(frame.lightDirection).xyz;
    half _785 = clamp(dot(_505, _556), half(0.0), half(1.0));
    half _797 = clamp(dot(_505, normalize(half3(_521) + _556)), half(0.0), half(1.0));
    half _842 = half(8192.0) * fma(half(-float(_785)), _685, _785 + _685);
    half _846 = half(1.0) / (half(params.facet_alpha) * _842);
    half _853 = half(2048.0) * half(params.facet_alpha);
    float3 _911 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _914 = dot(_911, _911);
    float3 _919 = _911 * rsqrt(fast::max(_914, 9.9999999392252902907785028219223e-09));
    float _923 = _914 * float(frame.punctualLights[0].positionFalloff.w);
    float _928 = fast::clamp(fma(-_923, _923, 1.0), 0.0, 1.0);
    float _947 = fast::clamp(fma(dot(-_919, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _980 = clamp(dot(_505, half3(_919)), half(0.0), half(1.0));
    half _992 = clamp(dot(_505, normalize(half3(_521) + half3(_919))), half(0.0), half(1.0));
    half _1037 = half(8192.0) * fma(half(-float(_980)), _685, _980 + _685);
    half _1041 = half(1.0) / (half(params.facet_alpha) * _1037);
    float3 _1106 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1109 = dot(_1106, _1106);
    float3 _1114 = _1106 * rsqrt(fast::max(_1109, 9.9999999392252902907785028219223e-09));
    float _1118 = _1109 * float(frame.punctualLights[1].positionFalloff.w);
    float _1123 = fast::clamp(fma(-_1118, _1118, 1.0), 0.0, 1.0);
    float _1142 = fast::clamp(fma(dot(-_1114, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1175 = clamp(dot(_505, half3(_1114)), half(0.0), half(1.0));
    half _1187 = clamp(dot(_505, normalize(half3(_521) + half3(_1114))), half(0.0), half(1.0));
    half _1232 = half(8192.0) * fma(half(-float(_1175)), _685, _1175 + _685);
    half _1236 = half(1.0) / (half(params.facet_alpha) * _1232);
    half3 _1265 = ((fma(half4(_763).xyz, _744 * _703, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_744.x, max(_744.y, _744.z)))), _703, half(1.0))) + min((_744 * ((((fma(_846, _842, half(2.0)) * pow(max(fma(half(-float(_797)), _797, half(1.0)), half(0.0)), half(0.5) * (_846 * _842))) * half(0.15915493667125701904296875)) * (_785 * (_846 * _853))) * _710)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_744 * ((((fma(_1041, _1037, half(2.0)) * pow(max(fma(half(-float(_992)), _992, half(1.0)), half(0.0)), half(0.5) * (_1041 * _1037))) * half(0.15915493667125701904296875)) * (_980 * (_1041 * _853))) * _710)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_928) * half(_928)) / fast::max(_914, 9.9999997473787516355514526367188e-05)) * half(_947)) * half(_947)), float3(65504.0))), half3(float3(65504.0)))) + min((_744 * ((((fma(_1236, _1232, half(2.0)) * pow(max(fma(half(-float(_1187)), _1187, half(1.0)), half(0.0)), half(0.5) * (_1236 * _1232))) * half(0.15915493667125701904296875)) * (_1175 * (_1236 * _853))) * _710)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1123) * half(_1123)) / fast::max(_1109, 9.9999997473787516355514526367188e-05)) * half(_1142)) * half(_1142)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1265, half(1.0)));
    return out;
}

