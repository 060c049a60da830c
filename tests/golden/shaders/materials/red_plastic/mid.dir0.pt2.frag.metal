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
    half3 _554 = normalize(half3(in.v_normal));
    float3 _570 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _718 = max(dot(_554, half3(_570)), half(9.9999997473787516355514526367188e-05));
    float4 _757 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_718, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _776 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_757).y) - half(1.0)));
    float4 _783 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_570), _554)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _828 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _831 = dot(_828, _828);
    float3 _836 = _828 * rsqrt(fast::max(_831, 9.9999999392252902907785028219223e-09));
    float _840 = _831 * float(frame.punctualLights[0].positionFalloff.w);
    float _845 = fast::clamp(fma(-_840, _840, 1.0), 0.0, 1.0);
    float _864 = fast::clamp(fma(dot(-_836, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _974 = normalize(half3(_570) + half3(_836));
    half _925 = clamp(dot(_554, half3(_836)), half(0.0), half(1.0));
    half3 _1001 = cross(_554, _974);
    half _1004 = clamp(dot(_554, _974), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1021 = max(mix((half(2.0) * _925) * _718, _925 + _718, half(params.facet_alpha)), half(0.000244140625));
    half _1023 = half(1024.0) * half(params.facet_alpha);
    half _1028 = _1023 / (fma(_1004, _1004, dot(_1001, _1001)) * (half(6433.98193359375) * _1021));
    float3 _1076 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1079 = dot(_1076, _1076);
    float3 _1084 = _1076 * rsqrt(fast::max(_1079, 9.9999999392252902907785028219223e-09));
    float _1088 = _1079 * float(frame.punctualLights[1].positionFalloff.w);
    float _1093 = fast::clamp(fma(-_1088, _1088, 1.0), 0.0, 1.0);
    float _1112 = fast::clamp(fma(dot(-_1084, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1222 = normalize(half3(_570) + half3(_1084));
    half _1173 = clamp(dot(_554, half3(_1084)), half(0.0), half(1.0));
    half3 _1249 = cross(_554, _1222);
    half _1252 = clamp(dot(_554, _1222), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1269 = max(mix((half(2.0) * _1173) * _718, _1173 + _718, half(params.facet_alpha)), half(0.000244140625));
    half _1276 = _1023 / (fma(_1252, _1252, dot(_1249, _1249)) * (half(6433.98193359375) * _1269));
    half3 _1288 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_783).xyz * (mix(half4(_757).xxx, half4(_757).yyy, half3(float3(params.facet_f0))) * _776)) + min(((half3(float3(params.facet_f0)) * min(_1028 * (_1028 * (half(6.283185482025146484375) * _1021)), half(65504.0))) * _776) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_845) * half(_845)) / fast::max(_831, 9.9999997473787516355514526367188e-05)) * half(_864)) * half(_864)), float3(65504.0))) * _925), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1276 * (_1276 * (half(6.283185482025146484375) * _1269)), half(65504.0))) * _776) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1093) * half(_1093)) / fast::max(_1079, 9.9999997473787516355514526367188e-05)) * half(_1112)) * half(_1112)), float3(65504.0))) * _1173), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1288, half(1.0)));
    return out;
}

