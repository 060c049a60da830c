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
    half _750 = max(dot(_557, half3(_573)), half(9.9999997473787516355514526367188e-05));
    float4 _789 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_750, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _808 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_789).y) - half(1.0)));
    float4 _815 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_573), _557)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _610 = half4(frame.lightDirection).xyz;
    half3 _922 = normalize(half3(_573) + _610);
    half _873 = clamp(dot(_557, _610), half(0.0), half(1.0));
    half3 _949 = cross(_557, _922);
    half _952 = clamp(dot(_557, _922), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _969 = max(mix((half(2.0) * _873) * _750, _873 + _750, half(params.facet_alpha)), half(0.000244140625));
    half _971 = half(1024.0) * half(params.facet_alpha);
    half _976 = _971 / (fma(_952, _952, dot(_949, _949)) * (half(6433.98193359375) * _969));
    float3 _1024 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1027 = dot(_1024, _1024);
    float3 _1032 = _1024 * rsqrt(fast::max(_1027, 9.9999999392252902907785028219223e-09));
    float _1036 = _1027 * float(frame.punctualLights[0].positionFalloff.w);
    float _1041 = fast::clamp(fma(-_1036, _1036, 1.0), 0.0, 1.0);
    float _1060 = fast::clamp(fma(dot(-_1032, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1170 = normalize(half3(_573) + half3(_1032));
    half _1121 = clamp(dot(_557, half3(_1032)), half(0.0), half(1.0));
    half3 _1197 = cross(_557, _1170);
    half _1200 = clamp(dot(_557, _1170), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1217 = max(mix((half(2.0) * _1121) * _750, _1121 + _750, half(params.facet_alpha)), half(0.000244140625));
    half _1224 = _971 / (fma(_1200, _1200, dot(_1197, _1197)) * (half(6433.98193359375) * _1217));
    float3 _1272 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1275 = dot(_1272, _1272);
    float3 _1280 = _1272 * rsqrt(fast::max(_1275, 9.9999999392252902907785028219223e-09));
    float _1284 = _1275 * float(frame.punctualLights[1].positionFalloff.w);
    float _1289 = fast::clamp(fma(-_1284, _1284, 1.0), 0.0, 1.0);
    float _1308 = fast::clamp(fma(dot(-_1280, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1418 = normalize(half3(_573) + half3(_1280));
    half _1369 = clamp(dot(_557, half3(_1280)), half(0.0), half(1.0));
    half3 _1445 = cross(_557, _1418);
    half _1448 = clamp(dot(_557, _1418), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1465 = max(mix((half(2.0) * _1369) * _750, _1369 + _750, half(params.facet_alpha)), half(0.000244140625));
    half _1472 = _971 / (fma(_1448, _1448, dot(_1445, _1445)) * (half(6433.98193359375) * _1465));
    half3 _1484 = (fma(half4(_815).xyz, mix(half4(_789).xxx, half4(_789).yyy, half3(float3(params.facet_f0))) * _808, min(((half3(float3(params.facet_f0)) * min(_976 * (_976 * (half(6.283185482025146484375) * _969)), half(65504.0))) * _808) * (half4(frame.lightColor).xyz * _873), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1224 * (_1224 * (half(6.283185482025146484375) * _1217)), half(65504.0))) * _808) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1041) * half(_1041)) / fast::max(_1027, 9.9999997473787516355514526367188e-05)) * half(_1060)) * half(_1060)), float3(65504.0))) * _1121), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1472 * (_1472 * (half(6.283185482025146484375) * _1465)), half(65504.0))) * _808) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1289) * half(_1289)) / fast::max(_1275, 9.9999997473787516355514526367188e-05)) * half(_1308)) * half(_1308)), float3(65504.0))) * _1369), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1484, half(1.0)));
    return out;
}

