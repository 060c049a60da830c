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
    half _744 = max(dot(_575, half3(_591)), half(9.9999997473787516355514526367188e-05));
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_744, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _802 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_783).y) - half(1.0)));
    float4 _809 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_591), _575)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _854 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _857 = dot(_854, _854);
    float3 _862 = _854 * rsqrt(fast::max(_857, 9.9999999392252902907785028219223e-09));
    float _866 = _857 * float(frame.punctualLights[0].positionFalloff.w);
    float _871 = fast::clamp(fma(-_866, _866, 1.0), 0.0, 1.0);
    float _890 = fast::clamp(fma(dot(-_862, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1000 = normalize(half3(_591) + half3(_862));
    half _951 = clamp(dot(_575, half3(_862)), half(0.0), half(1.0));
    half4 _1069 = half4(cross(_575, _1000), half(params.facet_alpha) * clamp(dot(_575, _1000), half(0.0), half(1.0))) * half(64.0);
    half _1043 = half(4096.0) * half(params.facet_alpha);
    half _1046 = half(6.283185482025146484375) * max(mix((half(2.0) * _951) * _744, _951 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1048 = _1043 / (dot(_1069, _1069) * _1046);
    float3 _1113 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1116 = dot(_1113, _1113);
    float3 _1121 = _1113 * rsqrt(fast::max(_1116, 9.9999999392252902907785028219223e-09));
    float _1125 = _1116 * float(frame.punctualLights[1].positionFalloff.w);
    float _1130 = fast::clamp(fma(-_1125, _1125, 1.0), 0.0, 1.0);
    float _1149 = fast::clamp(fma(dot(-_1121, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1259 = normalize(half3(_591) + half3(_1121));
    half _1210 = clamp(dot(_575, half3(_1121)), half(0.0), half(1.0));
    half4 _1328 = half4(cross(_575, _1259), half(params.facet_alpha) * clamp(dot(_575, _1259), half(0.0), half(1.0))) * half(64.0);
    half _1305 = half(6.283185482025146484375) * max(mix((half(2.0) * _1210) * _744, _1210 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1307 = _1043 / (dot(_1328, _1328) * _1305);
    half3 _1336 = fma(half4(_809).xyz, mix(half4(_783).xxx, half4(_783).yyy, half3(float3(params.facet_f0))) * _802, min(((half3(float3(params.facet_f0)) * min(_1048 * (_1048 * _1046), half(65504.0))) * _802) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_871) * half(_871)) / fast::max(_857, 9.9999997473787516355514526367188e-05)) * half(_890)) * half(_890)), float3(65504.0))) * _951), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1307 * (_1307 * _1305), half(65504.0))) * _802) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1130) * half(_1130)) / fast::max(_1116, 9.9999997473787516355514526367188e-05)) * half(_1149)) * half(_1149)), float3(65504.0))) * _1210), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1336, half(1.0)));
    return out;
}

