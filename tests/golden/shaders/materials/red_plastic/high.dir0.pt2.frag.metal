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
    half3 _567 = normalize(half3(in.v_normal));
    float3 _583 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _729 = max(dot(_567, half3(_583)), half(9.9999997473787516355514526367188e-05));
    float4 _762 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_729, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _778 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_583), _567)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _823 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _826 = dot(_823, _823);
    float3 _831 = _823 * rsqrt(fast::max(_826, 9.9999999392252902907785028219223e-09));
    float _835 = _826 * float(frame.punctualLights[0].positionFalloff.w);
    float _840 = fast::clamp(fma(-_835, _835, 1.0), 0.0, 1.0);
    float _859 = fast::clamp(fma(dot(-_831, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _967 = fast::normalize(_583 + _831);
    half _920 = clamp(dot(_567, half3(_831)), half(0.0), half(1.0));
    half3 _1007 = cross(_567, half3(_967));
    half _1010 = clamp(dot(_567, half3(_967)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1019 = half(params.facet_alpha) / fma(_1010, _1010, dot(_1007, _1007));
    half _1047 = half(1.0) - clamp(dot(half3(_831), half3(_967)), half(0.0), half(1.0));
    half _1050 = _1047 * _1047;
    half3 _1058 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1102 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1105 = dot(_1102, _1102);
    float3 _1110 = _1102 * rsqrt(fast::max(_1105, 9.9999999392252902907785028219223e-09));
    float _1114 = _1105 * float(frame.punctualLights[1].positionFalloff.w);
    float _1119 = fast::clamp(fma(-_1114, _1114, 1.0), 0.0, 1.0);
    float _1138 = fast::clamp(fma(dot(-_1110, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1246 = fast::normalize(_583 + _1110);
    half _1199 = clamp(dot(_567, half3(_1110)), half(0.0), half(1.0));
    half3 _1286 = cross(_567, half3(_1246));
    half _1289 = clamp(dot(_567, half3(_1246)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1298 = half(params.facet_alpha) / fma(_1289, _1289, dot(_1286, _1286));
    half _1326 = half(1.0) - clamp(dot(half3(_1110), half3(_1246)), half(0.0), half(1.0));
    half _1329 = _1326 * _1326;
    half3 _1345 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_778).xyz * mix(half4(_762).xxx, half4(_762).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + (_1058 * ((_1050 * _1050) * _1047))) * min(min((_1019 * _1019) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _920) * _729, _920 + _729, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_840) * half(_840)) / fast::max(_826, 9.9999997473787516355514526367188e-05)) * half(_859)) * half(_859)), float3(65504.0))) * _920), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1058 * ((_1329 * _1329) * _1326))) * min(min((_1298 * _1298) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1199) * _729, _1199 + _729, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1119) * half(_1119)) / fast::max(_1105, 9.9999997473787516355514526367188e-05)) * half(_1138)) * half(_1138)), float3(65504.0))) * _1199), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1345, half(1.0)));
    return out;
}

