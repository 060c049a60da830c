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
    half3 _536 = normalize(half3(in.v_normal));
    float3 _552 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _728 = reflect(-half3(_552), _536);
    float4 _764 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_536, half3(_552)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _790 = facet_environment.sample(facet_environmentSmplr, float3(_728), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _743 = mix(half4(_764).xxx, half4(_764).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_764).y) - half(1.0))));
    half3 _589 = half4(frame.lightDirection).xyz;
    half _919 = clamp(dot(_728, _589), half(0.0), half(1.0));
    half _922 = _919 * _919;
    half4 _1540 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_922 * _922, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _934 = _1540.x;
    float3 _979 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _982 = dot(_979, _979);
    float3 _987 = _979 * rsqrt(fast::max(_982, 9.9999999392252902907785028219223e-09));
    float _991 = _982 * float(frame.punctualLights[0].positionFalloff.w);
    float _996 = fast::clamp(fma(-_991, _991, 1.0), 0.0, 1.0);
    float _1015 = fast::clamp(fma(dot(-_987, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1147 = clamp(dot(_728, half3(_987)), half(0.0), half(1.0));
    half _1150 = _1147 * _1147;
    half4 _1565 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1150 * _1150, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1162 = _1565.x;
    float3 _1207 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1210 = dot(_1207, _1207);
    float3 _1215 = _1207 * rsqrt(fast::max(_1210, 9.9999999392252902907785028219223e-09));
    float _1219 = _1210 * float(frame.punctualLights[1].positionFalloff.w);
    float _1224 = fast::clamp(fma(-_1219, _1219, 1.0), 0.0, 1.0);
    float _1243 = fast::clamp(fma(dot(-_1215, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1375 = clamp(dot(_728, half3(_1215)), half(0.0), half(1.0));
    half _1378 = _1375 * _1375;
    half4 _1591 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1378 * _1378, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1390 = _1591.x;
    half3 _1399 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_790).xyz * _743) + min((_743 * ((_934 * _934) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_536, _589), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_743 * ((_1162 * _1162) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_996) * half(_996)) / fast::max(_982, 9.9999997473787516355514526367188e-05)) * half(_1015)) * half(_1015)), float3(65504.0))) * clamp(dot(_536, half3(_987)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_743 * ((_1390 * _1390) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1224) * half(_1224)) / fast::max(_1210, 9.9999997473787516355514526367188e-05)) * half(_1243)) * half(_1243)), float3(65504.0))) * clamp(dot(_536, half3(_1215)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1399, half(1.0)));
    return out;
}

