#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _575 = normalize(half3(in.v_normal));
    float3 _591 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _765 = max(dot(_575, half3(_591)), half(9.9999997473787516355514526367188e-05));
    float4 _804 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_765, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _823 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_804).y) - half(1.0)));
    float4 _830 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_591), _575)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _628 = half4(frame.lightDirection).xyz;
    half3 _937 = normalize(half3(_591) + _628);
    half _888 = clamp(dot(_575, _628), half(0.0), half(1.0));
    half4 _1006 = half4(cross(_575, _937), half(params.facet_alpha) * clamp(dot(_575, _937), half(0.0), half(1.0))) * half(64.0);
    half _980 = half(4096.0) * half(params.facet_alpha);
    half _983 = half(6.283185482025146484375) * max(mix((half(2.0) * _888) * _765, _888 + _765, half(params.facet_alpha)), half(0.000244140625));
    half _985 = _980 / (dot(_1006, _1006) * _983);
    float3 _1050 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1053 = dot(_1050, _1050);
    float3 _1058 = _1050 * rsqrt(fast::max(_1053, 9.9999999392252902907785028219223e-09));
    float _1062 = _1053 * float(frame.punctualLights[0].positionFalloff.w);
    float _1067 = fast::clamp(fma(-_1062, _1062, 1.0), 0.0, 1.0);
    float _1086 = fast::clamp(fma(dot(-_1058, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1196 = normalize(half3(_591) + half3(_1058));
    half _1147 = clamp(dot(_575, half3(_1058)), half(0.0), half(1.0));
    half4 _1265 = half4(cross(_575, _1196), half(params.facet_alpha) * clamp(dot(_575, _1196), half(0.0), half(1.0))) * half(64.0);
    half _1242 = half(6.283185482025146484375) * max(mix((half(2.0) * _1147) * _765, _1147 + _765, half(params.facet_alpha)), half(0.000244140625));
    half _1244 = _980 / (dot(_1265, _1265) * _1242);
    float3 _1309 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1312 = dot(_1309, _1309);
    float3 _1317 = _1309 * rsqrt(fast::max(_1312, 9.9999999392252902907785028219223e-09));
    float _1321 = _1312 * float(frame.punctualLights[1].positionFalloff.w);
    float _1326 = fast::clamp(fma(-_1321, _1321, 1.0), 0.0, 1.0);
    float _1345 = fast::clamp(fma(dot(-_1317, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1455 = normalize(half3(_591) + half3(_1317));
    half _1406 = clamp(dot(_575, half3(_1317)), half(0.0), half(1.0));
    half4 _1524 = half4(cross(_575, _1455), half(params.facet_alpha) * clamp(dot(_575, _1455), half(0.0), half(1.0))) * half(64.0);
    half _1501 = half(6.283185482025146484375) * max(mix((half(2.0) * _1406) * _765, _1406 + _765, half(params.facet_alpha)), half(0.000244140625));
    half _1503 = _980 / (dot(_1524, _1524) * _1501);
    half3 _1532 = (fma(half4(_830).xyz, mix(half4(_804).xxx, half4(_804).yyy, half3(float3(params.facet_f0))) * _823, min(((half3(float3(params.facet_f0)) * min(_985 * (_985 * _983), half(65504.0))) * _823) * (half4(frame.lightColor).xyz * _888), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1244 * (_1244 * _1242), half(65504.0))) * _823) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1067) * half(_1067)) / fast::max(_1053, 9.9999997473787516355514526367188e-05)) * half(_1086)) * half(_1086)), float3(65504.0))) * _1147), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1503 * (_1503 * _1501), half(65504.0))) * _823) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1326) * half(_1326)) / fast::max(_1312, 9.9999997473787516355514526367188e-05)) * half(_1345)) * half(_1345)), float3(65504.0))) * _1406), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1532, half(1.0)));
    return out;
}

