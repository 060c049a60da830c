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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _604 = normalize(half3(in.v_normal));
    float3 _610 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _797 = max(dot(_604, half3(_610)), half(9.9999997473787516355514526367188e-05));
    float4 _802 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_797, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _856 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1480 = half4(_802);
    half _815 = _1480.z;
    half _817 = fma(half(-float(max(_856.x, max(_856.y, _856.z)))), _815, half(1.0));
    half4 _1484 = half4(_802);
    half _822 = _1484.w;
    float4 _875 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_610), _604)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _912 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _915 = dot(_912, _912);
    float3 _920 = _912 * rsqrt(fast::max(_915, 9.9999999392252902907785028219223e-09));
    float _924 = _915 * float(frame.punctualLights[0].positionFalloff.w);
    float _929 = fast::clamp(fma(-_924, _924, 1.0), 0.0, 1.0);
    float _948 = fast::clamp(fma(dot(-_920, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _982 = dot(_604, half3(_920));
    half _984 = clamp(_982, half(0.0), half(1.0));
    half _996 = clamp(dot(_604, normalize(half3(_610) + half3(_920))), half(0.0), half(1.0));
    half _1065 = half(8192.0) * fma(half(-float(_984)), _797, _984 + _797);
    half _1069 = half(1.0) / (half(params.facet_alpha) * _1065);
    half _1076 = half(2048.0) * half(params.facet_alpha);
    half3 _1029 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_982 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_984), half3(float3(0.0)), half3(float3(1.0)))) * _817) + (_856 * ((((fma(_1069, _1065, half(2.0)) * pow(max(fma(half(-float(_996)), _996, half(1.0)), half(0.0)), half(0.5) * (_1069 * _1065))) * half(0.15915493667125701904296875)) * (_984 * (_1069 * _1076))) * _822))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_929) * half(_929)) / fast::max(_915, 9.9999997473787516355514526367188e-05)) * half(_948)) * half(_948)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1140 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1143 = dot(_1140, _1140);
    float3 _1148 = _1140 * rsqrt(fast::max(_1143, 9.9999999392252902907785028219223e-09));
    float _1152 = _1143 * float(frame.punctualLights[1].positionFalloff.w);
    float _1157 = fast::clamp(fma(-_1152, _1152, 1.0), 0.0, 1.0);
    float _1176 = fast::clamp(fma(dot(-_1148, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1210 = dot(_604, half3(_1148));
    half _1212 = clamp(_1210, half(0.0), half(1.0));
    half _1224 = clamp(dot(_604, normalize(half3(_610) + half3(_1148))), half(0.0), half(1.0));
    half _1293 = half(8192.0) * fma(half(-float(_1212)), _797, _1212 + _797);
    half _1297 = half(1.0) / (half(params.facet_alpha) * _1293);
    half3 _1257 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1210 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1212), half3(float3(0.0)), half3(float3(1.0)))) * _817) + (_856 * ((((fma(_1297, _1293, half(2.0)) * pow(max(fma(half(-float(_1224)), _1224, half(1.0)), half(0.0)), half(0.5) * (_1297 * _1293))) * half(0.15915493667125701904296875)) * (_1212 * (_1297 * _1076))) * _822))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1157) * half(_1157)) / fast::max(_1143, 9.9999997473787516355514526367188e-05)) * half(_1176)) * half(_1176)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1332 = (fma(half4(_875).xyz, _856 * _815, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _604.y)) + (half4(frame.sh[2]).xyz * _604.z)) + (half4(frame.sh[3]).xyz * _604.x), half3(float3(0.0)))) * _817) + _1029) + _1257;
    out.fragColor = float4(half4(_1332, half(1.0)));
    return out;
}

