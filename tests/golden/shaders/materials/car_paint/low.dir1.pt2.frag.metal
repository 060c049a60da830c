#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _637 = normalize(half3(in.v_normal));
    float3 _653 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _846 = max(dot(_637, half3(_653)), half(9.9999997473787516355514526367188e-05));
    half3 _850 = reflect(-half3(_653), _637);
    float4 _886 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_846, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _917 = facet_environment.sample(facet_environmentSmplr, float3(_850), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _865 = mix(half4(_886).xxx, half4(_886).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_886).y) - half(1.0))));
    half3 _691 = half4(frame.lightDirection).xyz;
    half _1046 = clamp(dot(_850, _691), half(0.0), half(1.0));
    half _1049 = _1046 * _1046;
    half4 _1772 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1049 * _1049, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1061 = _1772.x;
    float3 _1106 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1109 = dot(_1106, _1106);
    float3 _1114 = _1106 * rsqrt(fast::max(_1109, 9.9999999392252902907785028219223e-09));
    float _1118 = _1109 * float(frame.punctualLights[0].positionFalloff.w);
    float _1123 = fast::clamp(fma(-_1118, _1118, 1.0), 0.0, 1.0);
    float _1142 = fast::clamp(fma(dot(-_1114, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1274 = clamp(dot(_850, half3(_1114)), half(0.0), half(1.0));
    half _1277 = _1274 * _1274;
    half4 _1797 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1277 * _1277, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1289 = _1797.x;
    float3 _1334 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1337 = dot(_1334, _1334);
    float3 _1342 = _1334 * rsqrt(fast::max(_1337, 9.9999999392252902907785028219223e-09));
    float _1346 = _1337 * float(frame.punctualLights[1].positionFalloff.w);
    float _1351 = fast::clamp(fma(-_1346, _1346, 1.0), 0.0, 1.0);
    float _1370 = fast::clamp(fma(dot(-_1342, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1502 = clamp(dot(_850, half3(_1342)), half(0.0), half(1.0));
    half _1505 = _1502 * _1502;
    half4 _1823 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1505 * _1505, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1517 = _1823.x;
    half3 _1526 = (fma(half4(_917).xyz, _865, min((_865 * ((_1061 * _1061) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_637, _691), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_865 * ((_1289 * _1289) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1123) * half(_1123)) / fast::max(_1109, 9.9999997473787516355514526367188e-05)) * half(_1142)) * half(_1142)), float3(65504.0))) * clamp(dot(_637, half3(_1114)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_865 * ((_1517 * _1517) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1351) * half(_1351)) / fast::max(_1337, 9.9999997473787516355514526367188e-05)) * half(_1370)) * half(_1370)), float3(65504.0))) * clamp(dot(_637, half3(_1342)), half(0.0), half(1.0))), half3(float3(65504.0)));
    half _1565 = half(1.0) - _846;
    half _1568 = _1565 * _1565;
    half _1585 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1597 = facet_environment.sample(facet_environmentSmplr, float3(_850), level(_1585 * (half(4.0) * (half(2.0) - _1585))));
    out.fragColor = float4(half4(mix(_1526, half4(_1597).xyz, half3(fma(half(0.959999978542327880859375), (_1568 * _1568) * _1565, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

