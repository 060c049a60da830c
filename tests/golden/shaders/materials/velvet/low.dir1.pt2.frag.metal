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
    half3 _546 = normalize(half3(in.v_normal));
    float3 _562 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _701 = facet_irradiance.sample(facet_irradianceSmplr, float3(_546), level(0.0));
    half _741 = max(dot(_546, half3(_562)), half(9.9999997473787516355514526367188e-05));
    float4 _746 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_741, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1564 = half4(_746);
    half _759 = _1564.z;
    half _761 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _759, half(1.0));
    half4 _1568 = half4(_746);
    half _766 = _1568.w;
    float4 _775 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_562), _546)), level(params.facet_sheenLod));
    half3 _594 = half4(frame.lightDirection).xyz;
    half _831 = dot(_546, _594);
    half _833 = clamp(_831, half(0.0), half(1.0));
    half _845 = clamp(dot(_546, normalize(half3(_562) + _594)), half(0.0), half(1.0));
    half _914 = half(8192.0) * fma(half(-float(_833)), _741, _833 + _741);
    half _918 = half(1.0) / (half(params.facet_alpha) * _914);
    half _925 = half(2048.0) * half(params.facet_alpha);
    float3 _989 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _992 = dot(_989, _989);
    float3 _997 = _989 * rsqrt(fast::max(_992, 9.9999999392252902907785028219223e-09));
    float _1001 = _992 * float(frame.punctualLights[0].positionFalloff.w);
    float _1006 = fast::clamp(fma(-_1001, _1001, 1.0), 0.0, 1.0);
    float _1025 = fast::clamp(fma(dot(-_997, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1059 = dot(_546, half3(_997));
    half _1061 = clamp(_1059, half(0.0), half(1.0));
    half _1073 = clamp(dot(_546, normalize(half3(_562) + half3(_997))), half(0.0), half(1.0));
    half _1142 = half(8192.0) * fma(half(-float(_1061)), _741, _1061 + _741);
    half _1146 = half(1.0) / (half(params.facet_alpha) * _1142);
    half3 _1106 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1059 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1061), half3(float3(0.0)), half3(float3(1.0)))) * _761) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1146, _1142, half(2.0)) * pow(max(fma(half(-float(_1073)), _1073, half(1.0)), half(0.0)), half(0.5) * (_1146 * _1142))) * half(0.15915493667125701904296875)) * (_1061 * (_1146 * _925))) * _766))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1006) * half(_1006)) / fast::max(_992, 9.9999997473787516355514526367188e-05)) * half(_1025)) * half(_1025)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1181 = (fma(half4(_775).xyz, half3(float3(params.facet_sheenColor)) * _759, (half3(float3(params.facet_diffuseColor)) * half4(_701).xyz) * _761) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_831 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_833), half3(float3(0.0)), half3(float3(1.0)))) * _761) + (half3(float3(params.facet_sheenColor)) * ((((fma(_918, _914, half(2.0)) * pow(max(fma(half(-float(_845)), _845, half(1.0)), half(0.0)), half(0.5) * (_918 * _914))) * half(0.15915493667125701904296875)) * (_833 * (_918 * _925))) * _766))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1106;
    float3 _1217 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1220 = dot(_1217, _1217);
    float3 _1225 = _1217 * rsqrt(fast::max(_1220, 9.9999999392252902907785028219223e-09));
    float _1229 = _1220 * float(frame.punctualLights[1].positionFalloff.w);
    float _1234 = fast::clamp(fma(-_1229, _1229, 1.0), 0.0, 1.0);
    float _1253 = fast::clamp(fma(dot(-_1225, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1287 = dot(_546, half3(_1225));
    half _1289 = clamp(_1287, half(0.0), half(1.0));
    half _1301 = clamp(dot(_546, normalize(half3(_562) + half3(_1225))), half(0.0), half(1.0));
    half _1370 = half(8192.0) * fma(half(-float(_1289)), _741, _1289 + _741);
    half _1374 = half(1.0) / (half(params.facet_alpha) * _1370);
    half3 _1334 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1287 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1289), half3(float3(0.0)), half3(float3(1.0)))) * _761) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1374, _1370, half(2.0)) * pow(max(fma(half(-float(_1301)), _1301, half(1.0)), half(0.0)), half(0.5) * (_1374 * _1370))) * half(0.15915493667125701904296875)) * (_1289 * (_1374 * _925))) * _766))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1234) * half(_1234)) / fast::max(_1220, 9.9999997473787516355514526367188e-05)) * half(_1253)) * half(_1253)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1181 + _1334, half(1.0)));
    return out;
}

