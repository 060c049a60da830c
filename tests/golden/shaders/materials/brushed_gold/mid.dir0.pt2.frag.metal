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
    half3 _557 = normalize(half3(in.v_normal));
    float3 _573 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _729 = max(dot(_557, half3(_573)), half(9.9999997473787516355514526367188e-05));
    float4 _768 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_729, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _787 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_768).y) - half(1.0)));
    float4 _794 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_573), _557)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _839 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _842 = dot(_839, _839);
    float3 _847 = _839 * rsqrt(fast::max(_842, 9.9999999392252902907785028219223e-09));
    float _851 = _842 * float(frame.punctualLights[0].positionFalloff.w);
    float _856 = fast::clamp(fma(-_851, _851, 1.0), 0.0, 1.0);
    float _875 = fast::clamp(fma(dot(-_847, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _985 = normalize(half3(_573) + half3(_847));
    half _936 = clamp(dot(_557, half3(_847)), half(0.0), half(1.0));
    half3 _1012 = cross(_557, _985);
    half _1015 = clamp(dot(_557, _985), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1032 = max(mix((half(2.0) * _936) * _729, _936 + _729, half(params.facet_alpha)), half(0.000244140625));
    half _1034 = half(1024.0) * half(params.facet_alpha);
    half _1039 = _1034 / (fma(_1015, _1015, dot(_1012, _1012)) * (half(6433.98193359375) * _1032));
    float3 _1087 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1090 = dot(_1087, _1087);
    float3 _1095 = _1087 * rsqrt(fast::max(_1090, 9.9999999392252902907785028219223e-09));
    float _1099 = _1090 * float(frame.punctualLights[1].positionFalloff.w);
    float _1104 = fast::clamp(fma(-_1099, _1099, 1.0), 0.0, 1.0);
    float _1123 = fast::clamp(fma(dot(-_1095, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1233 = normalize(half3(_573) + half3(_1095));
    half _1184 = clamp(dot(_557, half3(_1095)), half(0.0), half(1.0));
    half3 _1260 = cross(_557, _1233);
    half _1263 = clamp(dot(_557, _1233), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1280 = max(mix((half(2.0) * _1184) * _729, _1184 + _729, half(params.facet_alpha)), half(0.000244140625));
    half _1287 = _1034 / (fma(_1263, _1263, dot(_1260, _1260)) * (half(6433.98193359375) * _1280));
    half3 _1299 = fma(half4(_794).xyz, mix(half4(_768).xxx, half4(_768).yyy, half3(float3(params.facet_f0))) * _787, min(((half3(float3(params.facet_f0)) * min(_1039 * (_1039 * (half(6.283185482025146484375) * _1032)), half(65504.0))) * _787) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_856) * half(_856)) / fast::max(_842, 9.9999997473787516355514526367188e-05)) * half(_875)) * half(_875)), float3(65504.0))) * _936), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1287 * (_1287 * (half(6.283185482025146484375) * _1280)), half(65504.0))) * _787) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1104) * half(_1104)) / fast::max(_1090, 9.9999997473787516355514526367188e-05)) * half(_1123)) * half(_1123)), float3(65504.0))) * _1184), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1299, half(1.0)));
    return out;
}

