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
    char _m8_pad[12];
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _486 = normalize(half3(in.v_normal));
    float3 _502 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _663 = max(dot(_486, half3(_502)), half(9.9999997473787516355514526367188e-05));
    float4 _668 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_663, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1365 = half4(_668);
    half _681 = _1365.z;
    half4 _1369 = half4(_668);
    half _688 = _1369.w;
    float4 _697 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_502), _486)), level(params.facet_sheenLod));
    half3 _537 = half4(frame.lightDirection).xyz;
    half _752 = clamp(dot(_486, _537), half(0.0), half(1.0));
    half _764 = clamp(dot(_486, normalize(half3(_502) + _537)), half(0.0), half(1.0));
    half _809 = half(8192.0) * fma(half(-float(_752)), _663, _752 + _663);
    half _813 = half(1.0) / (half(params.facet_alpha) * _809);
    half _820 = half(2048.0) * half(params.facet_alpha);
    float3 _878 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _881 = dot(_878, _878);
    float3 _886 = _878 * rsqrt(fast::max(_881, 9.9999999392252902907785028219223e-09));
    float _890 = _881 * float(frame.punctualLights[0].positionFalloff.w);
    float _895 = fast::clamp(fma(-_890, _890, 1.0), 0.0, 1.0);
    float _914 = fast::clamp(fma(dot(-_886, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _947 = clamp(dot(_486, half3(_886)), half(0.0), half(1.0));
    half _959 = clamp(dot(_486, normalize(half3(_502) + half3(_886))), half(0.0), half(1.0));
    half _1004 = half(8192.0) * fma(half(-float(_947)), _663, _947 + _663);
    half _1008 = half(1.0) / (half(params.facet_alpha) * _1004);
    half3 _1037 = (fma(half4(_697).xyz, half3(float3(params.facet_sheenColor)) * _681, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _681, half(1.0))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_813, _809, half(2.0)) * pow(max(fma(half(-float(_764)), _764, half(1.0)), half(0.0)), half(0.5) * (_813 * _809))) * half(0.15915493667125701904296875)) * (_752 * (_813 * _820))) * _688)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_1008, _1004, half(2.0)) * pow(max(fma(half(-float(_959)), _959, half(1.0)), half(0.0)), half(0.5) * (_1008 * _1004))) * half(0.15915493667125701904296875)) * (_947 * (_1008 * _820))) * _688)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_895) * half(_895)) / fast::max(_881, 9.9999997473787516355514526367188e-05)) * half(_914)) * half(_914)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1073 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1076 = dot(_1073, _1073);
    float3 _1081 = _1073 * rsqrt(fast::max(_1076, 9.9999999392252902907785028219223e-09));
    float _1085 = _1076 * float(frame.punctualLights[1].positionFalloff.w);
    float _1090 = fast::clamp(fma(-_1085, _1085, 1.0), 0.0, 1.0);
    float _1109 = fast::clamp(fma(dot(-_1081, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1142 = clamp(dot(_486, half3(_1081)), half(0.0), half(1.0));
    half _1154 = clamp(dot(_486, normalize(half3(_502) + half3(_1081))), half(0.0), half(1.0));
    half _1199 = half(8192.0) * fma(half(-float(_1142)), _663, _1142 + _663);
    half _1203 = half(1.0) / (half(params.facet_alpha) * _1199);
    out.fragColor = float4(half4(_1037 + min((half3(float3(params.facet_sheenColor)) * ((((fma(_1203, _1199, half(2.0)) * pow(max(fma(half(-float(_1154)), _1154, half(1.0)), half(0.0)), half(0.5) * (_1203 * _1199))) * half(0.15915493667125701904296875)) * (_1142 * (_1203 * _820))) * _688)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1090) * half(_1090)) / fast::max(_1076, 9.9999997473787516355514526367188e-05)) * half(_1109)) * half(_1109)), float3(65504.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

