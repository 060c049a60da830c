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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _583 = normalize(half3(in.v_normal));
    float3 _599 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _757 = max(dot(_583, half3(_599)), half(9.9999997473787516355514526367188e-05));
    float4 _796 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_757, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _815 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_796).y) - half(1.0)));
    float4 _822 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_599), _583)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _867 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _870 = dot(_867, _867);
    float3 _875 = _867 * rsqrt(fast::max(_870, 9.9999999392252902907785028219223e-09));
    float _879 = _870 * float(frame.punctualLights[0].positionFalloff.w);
    float _884 = fast::clamp(fma(-_879, _879, 1.0), 0.0, 1.0);
    float _903 = fast::clamp(fma(dot(-_875, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1013 = normalize(half3(_599) + half3(_875));
    half _964 = clamp(dot(_583, half3(_875)), half(0.0), half(1.0));
    half4 _1082 = half4(cross(_583, _1013), half(params.facet_alpha) * clamp(dot(_583, _1013), half(0.0), half(1.0))) * half(64.0);
    half _1056 = half(4096.0) * half(params.facet_alpha);
    half _1059 = half(6.283185482025146484375) * max(mix((half(2.0) * _964) * _757, _964 + _757, half(params.facet_alpha)), half(0.000244140625));
    half _1061 = _1056 / (dot(_1082, _1082) * _1059);
    float3 _1126 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1129 = dot(_1126, _1126);
    float3 _1134 = _1126 * rsqrt(fast::max(_1129, 9.9999999392252902907785028219223e-09));
    float _1138 = _1129 * float(frame.punctualLights[1].positionFalloff.w);
    float _1143 = fast::clamp(fma(-_1138, _1138, 1.0), 0.0, 1.0);
    float _1162 = fast::clamp(fma(dot(-_1134, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1272 = normalize(half3(_599) + half3(_1134));
    half _1223 = clamp(dot(_583, half3(_1134)), half(0.0), half(1.0));
    half4 _1341 = half4(cross(_583, _1272), half(params.facet_alpha) * clamp(dot(_583, _1272), half(0.0), half(1.0))) * half(64.0);
    half _1318 = half(6.283185482025146484375) * max(mix((half(2.0) * _1223) * _757, _1223 + _757, half(params.facet_alpha)), half(0.000244140625));
    half _1320 = _1056 / (dot(_1341, _1341) * _1318);
    half3 _1349 = fma(half4(_822).xyz, mix(half4(_796).xxx, half4(_796).yyy, half3(float3(params.facet_f0))) * _815, min(((half3(float3(params.facet_f0)) * min(_1061 * (_1061 * _1059), half(65504.0))) * _815) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_884) * half(_884)) / fast::max(_870, 9.9999997473787516355514526367188e-05)) * half(_903)) * half(_903)), float3(65504.0))) * _964), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1320 * (_1320 * _1318), half(65504.0))) * _815) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1143) * half(_1143)) / fast::max(_1129, 9.9999997473787516355514526367188e-05)) * half(_1162)) * half(_1162)), float3(65504.0))) * _1223), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1349, half(1.0)));
    return out;
}

