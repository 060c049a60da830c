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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _487 = normalize(half3(in.v_normal));
    float3 _503 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _647 = max(dot(_487, half3(_503)), half(9.9999997473787516355514526367188e-05));
    float4 _652 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_647, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1236 = half4(_652);
    half _665 = _1236.z;
    half4 _1240 = half4(_652);
    half _672 = _1240.w;
    float4 _681 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_503), _487)), level(params.facet_sheenLod));
    float3 _751 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _754 = dot(_751, _751);
    float3 _759 = _751 * rsqrt(fast::max(_754, 9.9999999392252902907785028219223e-09));
    float _763 = _754 * float(frame.punctualLights[0].positionFalloff.w);
    float _768 = fast::clamp(fma(-_763, _763, 1.0), 0.0, 1.0);
    float _787 = fast::clamp(fma(dot(-_759, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _820 = clamp(dot(_487, half3(_759)), half(0.0), half(1.0));
    half _832 = clamp(dot(_487, normalize(half3(_503) + half3(_759))), half(0.0), half(1.0));
    half _877 = half(8192.0) * fma(half(-float(_820)), _647, _820 + _647);
    half _881 = half(1.0) / (half(params.facet_alpha) * _877);
    half _888 = half(2048.0) * half(params.facet_alpha);
    float3 _946 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _949 = dot(_946, _946);
    float3 _954 = _946 * rsqrt(fast::max(_949, 9.9999999392252902907785028219223e-09));
    float _958 = _949 * float(frame.punctualLights[1].positionFalloff.w);
    float _963 = fast::clamp(fma(-_958, _958, 1.0), 0.0, 1.0);
    float _982 = fast::clamp(fma(dot(-_954, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1015 = clamp(dot(_487, half3(_954)), half(0.0), half(1.0));
    half _1027 = clamp(dot(_487, normalize(half3(_503) + half3(_954))), half(0.0), half(1.0));
    half _1072 = half(8192.0) * fma(half(-float(_1015)), _647, _1015 + _647);
    half _1076 = half(1.0) / (half(params.facet_alpha) * _1072);
    half3 _1105 = (fma(half4(_681).xyz, half3(float3(params.facet_sheenColor)) * _665, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _665, half(1.0))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_881, _877, half(2.0)) * pow(max(fma(half(-float(_832)), _832, half(1.0)), half(0.0)), half(0.5) * (_881 * _877))) * half(0.15915493667125701904296875)) * (_820 * (_881 * _888))) * _672)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_768) * half(_768)) / fast::max(_754, 9.9999997473787516355514526367188e-05)) * half(_787)) * half(_787)), float3(65504.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_1076, _1072, half(2.0)) * pow(max(fma(half(-float(_1027)), _1027, half(1.0)), half(0.0)), half(0.5) * (_1076 * _1072))) * half(0.15915493667125701904296875)) * (_1015 * (_1076 * _888))) * _672)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_963) * half(_963)) / fast::max(_949, 9.9999997473787516355514526367188e-05)) * half(_982)) * half(_982)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1105, half(1.0)));
    return out;
}

