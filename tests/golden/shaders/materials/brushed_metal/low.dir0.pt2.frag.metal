#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _656 = normalize(half3(in.v_normal));
    float3 _672 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _796 = half4(in.v_tangent).xyz;
    half _849 = max(dot(_656, half3(_672)), half(9.9999997473787516355514526367188e-05));
    half _958 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1581;
    if (float(_958) >= 0.0)
    {
        _1581 = _796;
    }
    else
    {
        _1581 = cross(_656, _796);
    }
    half _910 = dot(_1581, half3(_672));
    half _917 = min(abs(_958) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _922 = fma(half(-float(_917)), half(1.0) - _849, half(1.0));
    half _925 = _917 * _910;
    float4 _965 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_849, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _991 = facet_environment.sample(facet_environmentSmplr, float3(((((_656 * _922) + (_1581 * _925)) * (half(512.0) * fma(_922, _849, _925 * _910))) - (half3(_672) * (half(256.0) * fma(_922, _922, _925 * _925))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _870 = mix(half4(_965).xxx, half4(_965).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_965).y) - half(1.0))));
    float3 _1036 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1039 = dot(_1036, _1036);
    float3 _1044 = _1036 * rsqrt(fast::max(_1039, 9.9999999392252902907785028219223e-09));
    float _1048 = _1039 * float(frame.punctualLights[0].positionFalloff.w);
    float _1053 = fast::clamp(fma(-_1048, _1048, 1.0), 0.0, 1.0);
    float _1072 = fast::clamp(fma(dot(-_1044, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1188 = reflect(-half3(_672), _656);
    half _1204 = clamp(dot(_1188, half3(_1044)), half(0.0), half(1.0));
    half _1207 = _1204 * _1204;
    half4 _1654 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1207 * _1207, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1219 = _1654.x;
    float3 _1264 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1267 = dot(_1264, _1264);
    float3 _1272 = _1264 * rsqrt(fast::max(_1267, 9.9999999392252902907785028219223e-09));
    float _1276 = _1267 * float(frame.punctualLights[1].positionFalloff.w);
    float _1281 = fast::clamp(fma(-_1276, _1276, 1.0), 0.0, 1.0);
    float _1300 = fast::clamp(fma(dot(-_1272, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1432 = clamp(dot(_1188, half3(_1272)), half(0.0), half(1.0));
    half _1435 = _1432 * _1432;
    half4 _1680 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1435 * _1435, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1447 = _1680.x;
    half3 _1456 = fma(half4(_991).xyz, _870, min((_870 * ((_1219 * _1219) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1053) * half(_1053)) / fast::max(_1039, 9.9999997473787516355514526367188e-05)) * half(_1072)) * half(_1072)), float3(65504.0))) * clamp(dot(_656, half3(_1044)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_870 * ((_1447 * _1447) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1281) * half(_1281)) / fast::max(_1267, 9.9999997473787516355514526367188e-05)) * half(_1300)) * half(_1300)), float3(65504.0))) * clamp(dot(_656, half3(_1272)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1456, half(1.0)));
    return out;
}

