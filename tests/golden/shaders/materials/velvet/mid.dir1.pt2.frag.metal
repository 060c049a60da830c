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
    half _684 = max(dot(_505, half3(_521)), half(9.9999997473787516355514526367188e-05));
    float4 _689 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_684, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _743 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1399 = half4(_689);
    half _702 = _1399.z;
    half4 _1403 = half4(_689);
    half _709 = _1403.w;
    float4 _762 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_521), _505)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _556 = half4(frame.lightDirection).xyz;
    half _784 = clamp(dot(_505, _556), half(0.0), half(1.0));
    half _796 = clamp(dot(_505, normalize(half3(_521) + _556)), half(0.0), half(1.0));
    half _841 = half(8192.0) * fma(half(-float(_784)), _684, _784 + _684);
    half _845 = half(1.0) / (half(params.facet_alpha) * _841);
    half _852 = half(2048.0) * half(params.facet_alpha);
    float3 _910 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _913 = dot(_910, _910);
    float3 _918 = _910 * rsqrt(fast::max(_913, 9.9999999392252902907785028219223e-09));
    float _922 = _913 * float(frame.punctualLights[0].positionFalloff.w);
    float _927 = fast::clamp(fma(-_922, _922, 1.0), 0.0, 1.0);
    float _946 = fast::clamp(fma(dot(-_918, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _979 = clamp(dot(_505, half3(_918)), half(0.0), half(1.0));
    half _991 = clamp(dot(_505, normalize(half3(_521) + half3(_918))), half(0.0), half(1.0));
    half _1036 = half(8192.0) * fma(half(-float(_979)), _684, _979 + _684);
    half _1040 = half(1.0) / (half(params.facet_alpha) * _1036);
    float3 _1105 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1108 = dot(_1105, _1105);
    float3 _1113 = _1105 * rsqrt(fast::max(_1108, 9.9999999392252902907785028219223e-09));
    float _1117 = _1108 * float(frame.punctualLights[1].positionFalloff.w);
    float _1122 = fast::clamp(fma(-_1117, _1117, 1.0), 0.0, 1.0);
    float _1141 = fast::clamp(fma(dot(-_1113, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1174 = clamp(dot(_505, half3(_1113)), half(0.0), half(1.0));
    half _1186 = clamp(dot(_505, normalize(half3(_521) + half3(_1113))), half(0.0), half(1.0));
    half _1231 = half(8192.0) * fma(half(-float(_1174)), _684, _1174 + _684);
    half _1235 = half(1.0) / (half(params.facet_alpha) * _1231);
    half3 _1264 = ((fma(half4(_762).xyz, _743 * _702, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_743.x, max(_743.y, _743.z)))), _702, half(1.0))) + min((_743 * ((((fma(_845, _841, half(2.0)) * pow(max(fma(half(-float(_796)), _796, half(1.0)), half(0.0)), half(0.5) * (_845 * _841))) * half(0.15915493667125701904296875)) * (_784 * (_845 * _852))) * _709)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_743 * ((((fma(_1040, _1036, half(2.0)) * pow(max(fma(half(-float(_991)), _991, half(1.0)), half(0.0)), half(0.5) * (_1040 * _1036))) * half(0.15915493667125701904296875)) * (_979 * (_1040 * _852))) * _709)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_927) * half(_927)) / fast::max(_913, 9.9999997473787516355514526367188e-05)) * half(_946)) * half(_946)), float3(65504.0))), half3(float3(65504.0)))) + min((_743 * ((((fma(_1235, _1231, half(2.0)) * pow(max(fma(half(-float(_1186)), _1186, half(1.0)), half(0.0)), half(0.5) * (_1235 * _1231))) * half(0.15915493667125701904296875)) * (_1174 * (_1235 * _852))) * _709)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1122) * half(_1122)) / fast::max(_1108, 9.9999997473787516355514526367188e-05)) * half(_1141)) * half(_1141)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1264, half(1.0)));
    return out;
}

