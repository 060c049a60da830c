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
    half _660 = max(dot(_502, half3(_518)), half(9.9999997473787516355514526367188e-05));
    float4 _665 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_660, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _719 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1259 = half4(_665);
    half _678 = _1259.z;
    half4 _1263 = half4(_665);
    half _685 = _1263.w;
    float4 _735 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_518), _502)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _772 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _775 = dot(_772, _772);
    float3 _780 = _772 * rsqrt(fast::max(_775, 9.9999999392252902907785028219223e-09));
    float _784 = _775 * float(frame.punctualLights[0].positionFalloff.w);
    float _789 = fast::clamp(fma(-_784, _784, 1.0), 0.0, 1.0);
    float _808 = fast::clamp(fma(dot(-_780, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _841 = clamp(dot(_502, half3(_780)), half(0.0), half(1.0));
    half _853 = clamp(dot(_502, normalize(half3(_518) + half3(_780))), half(0.0), half(1.0));
    half _898 = half(8192.0) * fma(half(-float(_841)), _660, _841 + _660);
    half _902 = half(1.0) / (half(params.facet_alpha) * _898);
    half _909 = half(2048.0) * half(params.facet_alpha);
    float3 _967 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _970 = dot(_967, _967);
    float3 _975 = _967 * rsqrt(fast::max(_970, 9.9999999392252902907785028219223e-09));
    float _979 = _970 * float(frame.punctualLights[1].positionFalloff.w);
    float _984 = fast::clamp(fma(-_979, _979, 1.0), 0.0, 1.0);
    float _1003 = fast::clamp(fma(dot(-_975, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1036 = clamp(dot(_502, half3(_975)), half(0.0), half(1.0));
    half _1048 = clamp(dot(_502, normalize(half3(_518) + half3(_975))), half(0.0), half(1.0));
    half _1093 = half(8192.0) * fma(half(-float(_1036)), _660, _1036 + _660);
    half _1097 = half(1.0) / (half(params.facet_alpha) * _1093);
    half3 _1126 = (fma(half4(_735).xyz, _719 * _678, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_719.x, max(_719.y, _719.z)))), _678, half(1.0))) + min((_719 * ((((fma(_902, _898, half(2.0)) * pow(max(fma(half(-float(_853)), _853, half(1.0)), half(0.0)), half(0.5) * (_902 * _898))) * half(0.15915493667125701904296875)) * (_841 * (_902 * _909))) * _685)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_789) * half(_789)) / fast::max(_775, 9.9999997473787516355514526367188e-05)) * half(_808)) * half(_808)), float3(65504.0))), half3(float3(65504.0)))) + min((_719 * ((((fma(_1097, _1093, half(2.0)) * pow(max(fma(half(-float(_1048)), _1048, half(1.0)), half(0.0)), half(0.5) * (_1097 * _1093))) * half(0.15915493667125701904296875)) * (_1036 * (_1097 * _909))) * _685)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_984) * half(_984)) / fast::max(_970, 9.9999997473787516355514526367188e-05)) * half(_1003)) * half(_1003)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1126, half(1.0)));
    return out;
}

