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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _547 = normalize(half3(in.v_normal));
    float3 _563 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _697 = facet_irradiance.sample(facet_irradianceSmplr, float3(_547), level(0.0));
    half _737 = max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05));
    float4 _742 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_737, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1566 = half4(_742);
    half _755 = _1566.z;
    half _757 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _755, half(1.0));
    half4 _1570 = half4(_742);
    half _762 = _1570.w;
    float4 _771 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_563), _547)), level(params.facet_sheenLod));
    half _827 = dot(_547, half3(frame.lightDirection.xyz));
    half _829 = clamp(_827, half(0.0), half(1.0));
    half _841 = clamp(dot(_547, half3(fast::normalize(_563 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _912 = half(8192.0) * fma(half(-float(_829)), _737, _829 + _737);
    half _916 = half(1.0) / (half(params.facet_alpha) * _912);
    half _923 = half(2048.0) * half(params.facet_alpha);
    float3 _987 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _990 = dot(_987, _987);
    float3 _995 = _987 * rsqrt(fast::max(_990, 9.9999999392252902907785028219223e-09));
    float _999 = _990 * float(frame.punctualLights[0].positionFalloff.w);
    float _1004 = fast::clamp(fma(-_999, _999, 1.0), 0.0, 1.0);
    float _1023 = fast::clamp(fma(dot(-_995, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1057 = dot(_547, half3(_995));
    half _1059 = clamp(_1057, half(0.0), half(1.0));
    half _1071 = clamp(dot(_547, half3(fast::normalize(_563 + _995))), half(0.0), half(1.0));
    half _1142 = half(8192.0) * fma(half(-float(_1059)), _737, _1059 + _737);
    half _1146 = half(1.0) / (half(params.facet_alpha) * _1142);
    half3 _1104 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1057 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1059), half3(float3(0.0)), half3(float3(1.0)))) * _757) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1146, _1142, half(2.0)) * pow(max(fma(half(-float(_1071)), _1071, half(1.0)), half(0.0)), half(0.5) * (_1146 * _1142))) * half(0.15915493667125701904296875)) * (_1059 * (_1146 * _923))) * _762))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1004) * half(_1004)) / fast::max(_990, 9.9999997473787516355514526367188e-05)) * half(_1023)) * half(_1023)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1181 = (fma(half4(_771).xyz, half3(float3(params.facet_sheenColor)) * _755, (half3(float3(params.facet_diffuseColor)) * half4(_697).xyz) * _757) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_827 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_829), half3(float3(0.0)), half3(float3(1.0)))) * _757) + (half3(float3(params.facet_sheenColor)) * ((((fma(_916, _912, half(2.0)) * pow(max(fma(half(-float(_841)), _841, half(1.0)), half(0.0)), half(0.5) * (_916 * _912))) * half(0.15915493667125701904296875)) * (_829 * (_916 * _923))) * _762))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1104;
    float3 _1217 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1220 = dot(_1217, _1217);
    float3 _1225 = _1217 * rsqrt(fast::max(_1220, 9.9999999392252902907785028219223e-09));
    float _1229 = _1220 * float(frame.punctualLights[1].positionFalloff.w);
    float _1234 = fast::clamp(fma(-_1229, _1229, 1.0), 0.0, 1.0);
    float _1253 = fast::clamp(fma(dot(-_1225, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1287 = dot(_547, half3(_1225));
    half _1289 = clamp(_1287, half(0.0), half(1.0));
    half _1301 = clamp(dot(_547, half3(fast::normalize(_563 + _1225))), half(0.0), half(1.0));
    half _1372 = half(8192.0) * fma(half(-float(_1289)), _737, _1289 + _737);
    half _1376 = half(1.0) / (half(params.facet_alpha) * _1372);
    half3 _1334 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1287 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1289), half3(float3(0.0)), half3(float3(1.0)))) * _757) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1376, _1372, half(2.0)) * pow(max(fma(half(-float(_1301)), _1301, half(1.0)), half(0.0)), half(0.5) * (_1376 * _1372))) * half(0.15915493667125701904296875)) * (_1289 * (_1376 * _923))) * _762))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1234) * half(_1234)) / fast::max(_1220, 9.9999997473787516355514526367188e-05)) * half(_1253)) * half(_1253)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1181 + _1334, half(1.0)));
    return out;
}

