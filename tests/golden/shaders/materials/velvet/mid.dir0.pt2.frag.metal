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
    half3 _479 = normalize(half3(in.v_normal));
    float3 _495 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _637 = max(dot(_479, half3(_495)), half(9.9999997473787516355514526367188e-05));
    float4 _642 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_637, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _688 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1241 = half4(_642);
    half _655 = _1241.z;
    half4 _1245 = half4(_642);
    half _659 = _1245.w;
    float4 _695 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_495), _479)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _732 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _735 = dot(_732, _732);
    float3 _740 = _732 * rsqrt(fast::max(_735, 9.9999999392252902907785028219223e-09));
    float _744 = _735 * float(frame.punctualLights[0].positionFalloff.w);
    float _749 = fast::clamp(fma(-_744, _744, 1.0), 0.0, 1.0);
    float _768 = fast::clamp(fma(dot(-_740, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _805 = clamp(dot(_479, half3(_740)), half(0.0), half(1.0));
    half _819 = clamp(dot(_479, normalize(half3(_495) + half3(_740))), half(0.0), half(1.0));
    half _877 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _880 = half(0.5) / half(params.facet_alpha);
    float3 _936 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _939 = dot(_936, _936);
    float3 _944 = _936 * rsqrt(fast::max(_939, 9.9999999392252902907785028219223e-09));
    float _948 = _939 * float(frame.punctualLights[1].positionFalloff.w);
    float _953 = fast::clamp(fma(-_948, _948, 1.0), 0.0, 1.0);
    float _972 = fast::clamp(fma(dot(-_944, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1009 = clamp(dot(_479, half3(_944)), half(0.0), half(1.0));
    half _1023 = clamp(dot(_479, normalize(half3(_495) + half3(_944))), half(0.0), half(1.0));
    half3 _1104 = (fma(half4(_695).xyz, _688 * _655, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_688.x, max(_688.y, _688.z)))), _655, half(1.0))) + min((_688 * ((((_877 * pow(max(fma(half(-float(_819)), _819, half(1.0)), half(0.0)), _880)) * half(0.15915493667125701904296875)) * (_805 / (half(4.0) * fma(half(-float(_805)), _637, _805 + _637)))) * _659)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_749) * half(_749)) / fast::max(_735, 9.9999997473787516355514526367188e-05)) * half(_768)) * half(_768)), float3(65504.0))), half3(float3(65504.0)))) + min((_688 * ((((_877 * pow(max(fma(half(-float(_1023)), _1023, half(1.0)), half(0.0)), _880)) * half(0.15915493667125701904296875)) * (_1009 / (half(4.0) * fma(half(-float(_1009)), _637, _1009 + _637)))) * _659)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_953) * half(_953)) / fast::max(_939, 9.9999997473787516355514526367188e-05)) * half(_972)) * half(_972)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1104, half(1.0)));
    return out;
}

