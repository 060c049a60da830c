#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
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
    half3 _559 = normalize(half3(in.v_normal));
    float3 _575 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _723 = max(dot(_559, half3(_575)), half(9.9999997473787516355514526367188e-05));
    float4 _762 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_723, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _781 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_762).y) - half(1.0)));
    float4 _793 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_575), _559)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _838 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _841 = dot(_838, _838);
    float3 _846 = _838 * rsqrt(fast::max(_841, 9.9999999392252902907785028219223e-09));
    float _850 = _841 * float(frame.punctualLights[0].positionFalloff.w);
    float _855 = fast::clamp(fma(-_850, _850, 1.0), 0.0, 1.0);
    float _874 = fast::clamp(fma(dot(-_846, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _984 = normalize(half3(_575) + half3(_846));
    half _935 = clamp(dot(_559, half3(_846)), half(0.0), half(1.0));
    half3 _1011 = cross(_559, _984);
    half _1014 = clamp(dot(_559, _984), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1031 = max(mix((half(2.0) * _935) * _723, _935 + _723, half(params.facet_alpha)), half(0.000244140625));
    half _1033 = half(1024.0) * half(params.facet_alpha);
    half _1038 = _1033 / (fma(_1014, _1014, dot(_1011, _1011)) * (half(6433.98193359375) * _1031));
    float3 _1086 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1089 = dot(_1086, _1086);
    float3 _1094 = _1086 * rsqrt(fast::max(_1089, 9.9999999392252902907785028219223e-09));
    float _1098 = _1089 * float(frame.punctualLights[1].positionFalloff.w);
    float _1103 = fast::clamp(fma(-_1098, _1098, 1.0), 0.0, 1.0);
    float _1122 = fast::clamp(fma(dot(-_1094, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1232 = normalize(half3(_575) + half3(_1094));
    half _1183 = clamp(dot(_559, half3(_1094)), half(0.0), half(1.0));
    half3 _1259 = cross(_559, _1232);
    half _1262 = clamp(dot(_559, _1232), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1279 = max(mix((half(2.0) * _1183) * _723, _1183 + _723, half(params.facet_alpha)), half(0.000244140625));
    half _1286 = _1033 / (fma(_1262, _1262, dot(_1259, _1259)) * (half(6433.98193359375) * _1279));
    half3 _1298 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_793).xyz * (mix(half4(_762).xxx, half4(_762).yyy, half3(float3(params.facet_f0))) * _781)) + min(((half3(float3(params.facet_f0)) * min(_1038 * (_1038 * (half(6.283185482025146484375) * _1031)), half(65504.0))) * _781) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_855) * half(_855)) / fast::max(_841, 9.9999997473787516355514526367188e-05)) * half(_874)) * half(_874)), float3(65504.0))) * _935), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1286 * (_1286 * (half(6.283185482025146484375) * _1279)), half(65504.0))) * _781) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1103) * half(_1103)) / fast::max(_1089, 9.9999997473787516355514526367188e-05)) * half(_1122)) * half(_1122)), float3(65504.0))) * _1183), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1298, half(1.0)));
    return out;
}

