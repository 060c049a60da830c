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
    half3 _572 = normalize(half3(in.v_normal));
    float3 _588 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _736 = max(dot(_572, half3(_588)), half(9.9999997473787516355514526367188e-05));
    float4 _775 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_736, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _794 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_775).y) - half(1.0)));
    float4 _801 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_588), _572)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _846 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _849 = dot(_846, _846);
    float3 _854 = _846 * rsqrt(fast::max(_849, 9.9999999392252902907785028219223e-09));
    float _858 = _849 * float(frame.punctualLights[0].positionFalloff.w);
    float _863 = fast::clamp(fma(-_858, _858, 1.0), 0.0, 1.0);
    float _882 = fast::clamp(fma(dot(-_854, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _992 = normalize(half3(_588) + half3(_854));
    half _943 = clamp(dot(_572, half3(_854)), half(0.0), half(1.0));
    half4 _1061 = half4(cross(_572, _992), half(params.facet_alpha) * clamp(dot(_572, _992), half(0.0), half(1.0))) * half(64.0);
    half _1035 = half(4096.0) * half(params.facet_alpha);
    half _1038 = half(6.283185482025146484375) * max(mix((half(2.0) * _943) * _736, _943 + _736, half(params.facet_alpha)), half(0.000244140625));
    half _1040 = _1035 / (dot(_1061, _1061) * _1038);
    float3 _1105 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1108 = dot(_1105, _1105);
    float3 _1113 = _1105 * rsqrt(fast::max(_1108, 9.9999999392252902907785028219223e-09));
    float _1117 = _1108 * float(frame.punctualLights[1].positionFalloff.w);
    float _1122 = fast::clamp(fma(-_1117, _1117, 1.0), 0.0, 1.0);
    float _1141 = fast::clamp(fma(dot(-_1113, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1251 = normalize(half3(_588) + half3(_1113));
    half _1202 = clamp(dot(_572, half3(_1113)), half(0.0), half(1.0));
    half4 _1320 = half4(cross(_572, _1251), half(params.facet_alpha) * clamp(dot(_572, _1251), half(0.0), half(1.0))) * half(64.0);
    half _1297 = half(6.283185482025146484375) * max(mix((half(2.0) * _1202) * _736, _1202 + _736, half(params.facet_alpha)), half(0.000244140625));
    half _1299 = _1035 / (dot(_1320, _1320) * _1297);
    half3 _1328 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_801).xyz * (mix(half4(_775).xxx, half4(_775).yyy, half3(float3(params.facet_f0))) * _794)) + min(((half3(float3(params.facet_f0)) * min(_1040 * (_1040 * _1038), half(65504.0))) * _794) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_863) * half(_863)) / fast::max(_849, 9.9999997473787516355514526367188e-05)) * half(_882)) * half(_882)), float3(65504.0))) * _943), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1299 * (_1299 * _1297), half(65504.0))) * _794) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1122) * half(_1122)) / fast::max(_1108, 9.9999997473787516355514526367188e-05)) * half(_1141)) * half(_1141)), float3(65504.0))) * _1202), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1328, half(1.0)));
    return out;
}

