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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _542 = normalize(half3(in.v_normal));
    float3 _558 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _734 = reflect(-half3(_558), _542);
    float4 _770 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_542, half3(_558)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _801 = facet_environment.sample(facet_environmentSmplr, float3(_734), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _749 = mix(half4(_770).xxx, half4(_770).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_770).y) - half(1.0))));
    half3 _595 = half4(frame.lightDirection).xyz;
    half _930 = clamp(dot(_734, _595), half(0.0), half(1.0));
    half _933 = _930 * _930;
    half4 _1553 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_933 * _933, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _945 = _1553.x;
    float3 _990 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _993 = dot(_990, _990);
    float3 _998 = _990 * rsqrt(fast::max(_993, 9.9999999392252902907785028219223e-09));
    float _1002 = _993 * float(frame.punctualLights[0].positionFalloff.w);
    float _1007 = fast::clamp(fma(-_1002, _1002, 1.0), 0.0, 1.0);
    float _1026 = fast::clamp(fma(dot(-_998, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1158 = clamp(dot(_734, half3(_998)), half(0.0), half(1.0));
    half _1161 = _1158 * _1158;
    half4 _1578 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1161 * _1161, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1173 = _1578.x;
    float3 _1218 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1221 = dot(_1218, _1218);
    float3 _1226 = _1218 * rsqrt(fast::max(_1221, 9.9999999392252902907785028219223e-09));
    float _1230 = _1221 * float(frame.punctualLights[1].positionFalloff.w);
    float _1235 = fast::clamp(fma(-_1230, _1230, 1.0), 0.0, 1.0);
    float _1254 = fast::clamp(fma(dot(-_1226, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1386 = clamp(dot(_734, half3(_1226)), half(0.0), half(1.0));
    half _1389 = _1386 * _1386;
    half4 _1604 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1389 * _1389, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1401 = _1604.x;
    half3 _1410 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_801).xyz * _749) + min((_749 * ((_945 * _945) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_542, _595), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_749 * ((_1173 * _1173) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1007) * half(_1007)) / fast::max(_993, 9.9999997473787516355514526367188e-05)) * half(_1026)) * half(_1026)), float3(65504.0))) * clamp(dot(_542, half3(_998)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_749 * ((_1401 * _1401) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1235) * half(_1235)) / fast::max(_1221, 9.9999997473787516355514526367188e-05)) * half(_1254)) * half(_1254)), float3(65504.0))) * clamp(dot(_542, half3(_1226)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1410, half(1.0)));
    return out;
}

