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
    half _682 = max(dot(_502, half3(_518)), half(9.9999997473787516355514526367188e-05));
    float4 _687 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_682, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _741 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1394 = half4(_687);
    half _700 = _1394.z;
    half4 _1398 = half4(_687);
    half _707 = _1398.w;
    float4 _757 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_518), _502)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _553 = half4(frame.lightDirection).xyz;
    half _779 = clamp(dot(_502, _553), half(0.0), half(1.0));
    half _791 = clamp(dot(_502, normalize(half3(_518) + _553)), half(0.0), half(1.0));
    half _836 = half(8192.0) * fma(half(-float(_779)), _682, _779 + _682);
    half _840 = half(1.0) / (half(params.facet_alpha) * _836);
    half _847 = half(2048.0) * half(params.facet_alpha);
    float3 _905 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _908 = dot(_905, _905);
    float3 _913 = _905 * rsqrt(fast::max(_908, 9.9999999392252902907785028219223e-09));
    float _917 = _908 * float(frame.punctualLights[0].positionFalloff.w);
    float _922 = fast::clamp(fma(-_917, _917, 1.0), 0.0, 1.0);
    float _941 = fast::clamp(fma(dot(-_913, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _974 = clamp(dot(_502, half3(_913)), half(0.0), half(1.0));
    half _986 = clamp(dot(_502, normalize(half3(_518) + half3(_913))), half(0.0), half(1.0));
    half _1031 = half(8192.0) * fma(half(-float(_974)), _682, _974 + _682);
    half _1035 = half(1.0) / (half(params.facet_alpha) * _1031);
    float3 _1100 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1103 = dot(_1100, _1100);
    float3 _1108 = _1100 * rsqrt(fast::max(_1103, 9.9999999392252902907785028219223e-09));
    float _1112 = _1103 * float(frame.punctualLights[1].positionFalloff.w);
    float _1117 = fast::clamp(fma(-_1112, _1112, 1.0), 0.0, 1.0);
    float _1136 = fast::clamp(fma(dot(-_1108, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1169 = clamp(dot(_502, half3(_1108)), half(0.0), half(1.0));
    half _1181 = clamp(dot(_502, normalize(half3(_518) + half3(_1108))), half(0.0), half(1.0));
    half _1226 = half(8192.0) * fma(half(-float(_1169)), _682, _1169 + _682);
    half _1230 = half(1.0) / (half(params.facet_alpha) * _1226);
    half3 _1259 = ((fma(half4(_757).xyz, _741 * _700, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_741.x, max(_741.y, _741.z)))), _700, half(1.0))) + min((_741 * ((((fma(_840, _836, half(2.0)) * pow(max(fma(half(-float(_791)), _791, half(1.0)), half(0.0)), half(0.5) * (_840 * _836))) * half(0.15915493667125701904296875)) * (_779 * (_840 * _847))) * _707)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_741 * ((((fma(_1035, _1031, half(2.0)) * pow(max(fma(half(-float(_986)), _986, half(1.0)), half(0.0)), half(0.5) * (_1035 * _1031))) * half(0.15915493667125701904296875)) * (_974 * (_1035 * _847))) * _707)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_922) * half(_922)) / fast::max(_908, 9.9999997473787516355514526367188e-05)) * half(_941)) * half(_941)), float3(65504.0))), half3(float3(65504.0)))) + min((_741 * ((((fma(_1230, _1226, half(2.0)) * pow(max(fma(half(-float(_1181)), _1181, half(1.0)), half(0.0)), half(0.5) * (_1230 * _1226))) * half(0.15915493667125701904296875)) * (_1169 * (_1230 * _847))) * _707)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1117) * half(_1117)) / fast::max(_1103, 9.9999997473787516355514526367188e-05)) * half(_1136)) * half(_1136)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1259, half(1.0)));
    return out;
}

