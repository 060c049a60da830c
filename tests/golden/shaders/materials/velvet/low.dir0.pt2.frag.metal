#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _506 = normalize(half3(in.v_normal));
    float3 _522 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _668 = max(dot(_506, half3(_522)), half(9.9999997473787516355514526367188e-05));
    float4 _673 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_668, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _727 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1270 = half4(_673);
    half _686 = _1270.z;
    half4 _1274 = half4(_673);
    half _693 = _1274.w;
    float4 _746 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_522), _506)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _783 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _786 = dot(_783, _783);
    float3 _791 = _783 * rsqrt(fast::max(_786, 9.9999999392252902907785028219223e-09));
    float _795 = _786 * float(frame.punctualLights[0].positionFalloff.w);
    float _800 = fast::clamp(fma(-_795, _795, 1.0), 0.0, 1.0);
    float _819 = fast::clamp(fma(dot(-_791, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _852 = clamp(dot(_506, half3(_791)), half(0.0), half(1.0));
    half _864 = clamp(dot(_506, normalize(half3(_522) + half3(_791))), half(0.0), half(1.0));
    half _909 = half(8192.0) * fma(half(-float(_852)), _668, _852 + _668);
    half _913 = half(1.0) / (half(params.facet_alpha) * _909);
    half _920 = half(2048.0) * half(params.facet_alpha);
    float3 _978 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _981 = dot(_978, _978);
    float3 _986 = _978 * rsqrt(fast::max(_981, 9.9999999392252902907785028219223e-09));
    float _990 = _981 * float(frame.punctualLights[1].positionFalloff.w);
    float _995 = fast::clamp(fma(-_990, _990, 1.0), 0.0, 1.0);
    float _1014 = fast::clamp(fma(dot(-_986, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1047 = clamp(dot(_506, half3(_986)), half(0.0), half(1.0));
    half _1059 = clamp(dot(_506, normalize(half3(_522) + half3(_986))), half(0.0), half(1.0));
    half _1104 = half(8192.0) * fma(half(-float(_1047)), _668, _1047 + _668);
    half _1108 = half(1.0) / (half(params.facet_alpha) * _1104);
    half3 _1137 = (fma(half4(_746).xyz, _727 * _686, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_727.x, max(_727.y, _727.z)))), _686, half(1.0))) + min((_727 * ((((fma(_913, _909, half(2.0)) * pow(max(fma(half(-float(_864)), _864, half(1.0)), half(0.0)), half(0.5) * (_913 * _909))) * half(0.15915493667125701904296875)) * (_852 * (_913 * _920))) * _693)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_800) * half(_800)) / fast::max(_786, 9.9999997473787516355514526367188e-05)) * half(_819)) * half(_819)), float3(65504.0))), half3(float3(65504.0)))) + min((_727 * ((((fma(_1108, _1104, half(2.0)) * pow(max(fma(half(-float(_1059)), _1059, half(1.0)), half(0.0)), half(0.5) * (_1108 * _1104))) * half(0.15915493667125701904296875)) * (_1047 * (_1108 * _920))) * _693)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_995) * half(_995)) / fast::max(_981, 9.9999997473787516355514526367188e-05)) * half(_1014)) * half(_1014)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1137, half(1.0)));
    return out;
}

