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
    half _747 = max(dot(_557, half3(_573)), half(9.9999997473787516355514526367188e-05));
    float4 _786 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_747, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _805 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_786).y) - half(1.0)));
    float4 _812 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_573), _557)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _610 = half4(frame.lightDirection).xyz;
    half3 _919 = normalize(half3(_573) + _610);
    half _870 = clamp(dot(_557, _610), half(0.0), half(1.0));
    half3 _946 = cross(_557, _919);
    half _949 = clamp(dot(_557, _919), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _966 = max(mix((half(2.0) * _870) * _747, _870 + _747, half(params.facet_alpha)), half(0.000244140625));
    half _968 = half(1024.0) * half(params.facet_alpha);
    half _973 = _968 / (fma(_949, _949, dot(_946, _946)) * (half(6433.98193359375) * _966));
    float3 _1021 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1024 = dot(_1021, _1021);
    float3 _1029 = _1021 * rsqrt(fast::max(_1024, 9.9999999392252902907785028219223e-09));
    float _1033 = _1024 * float(frame.punctualLights[0].positionFalloff.w);
    float _1038 = fast::clamp(fma(-_1033, _1033, 1.0), 0.0, 1.0);
    float _1057 = fast::clamp(fma(dot(-_1029, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1167 = normalize(half3(_573) + half3(_1029));
    half _1118 = clamp(dot(_557, half3(_1029)), half(0.0), half(1.0));
    half3 _1194 = cross(_557, _1167);
    half _1197 = clamp(dot(_557, _1167), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1214 = max(mix((half(2.0) * _1118) * _747, _1118 + _747, half(params.facet_alpha)), half(0.000244140625));
    half _1221 = _968 / (fma(_1197, _1197, dot(_1194, _1194)) * (half(6433.98193359375) * _1214));
    float3 _1269 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1272 = dot(_1269, _1269);
    float3 _1277 = _1269 * rsqrt(fast::max(_1272, 9.9999999392252902907785028219223e-09));
    float _1281 = _1272 * float(frame.punctualLights[1].positionFalloff.w);
    float _1286 = fast::clamp(fma(-_1281, _1281, 1.0), 0.0, 1.0);
    float _1305 = fast::clamp(fma(dot(-_1277, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1415 = normalize(half3(_573) + half3(_1277));
    half _1366 = clamp(dot(_557, half3(_1277)), half(0.0), half(1.0));
    half3 _1442 = cross(_557, _1415);
    half _1445 = clamp(dot(_557, _1415), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1462 = max(mix((half(2.0) * _1366) * _747, _1366 + _747, half(params.facet_alpha)), half(0.000244140625));
    half _1469 = _968 / (fma(_1445, _1445, dot(_1442, _1442)) * (half(6433.98193359375) * _1462));
    half3 _1481 = (fma(half4(_812).xyz, mix(half4(_786).xxx, half4(_786).yyy, half3(float3(params.facet_f0))) * _805, min(((half3(float3(params.facet_f0)) * min(_973 * (_973 * (half(6.283185482025146484375) * _966)), half(65504.0))) * _805) * (half4(frame.lightColor).xyz * _870), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1221 * (_1221 * (half(6.283185482025146484375) * _1214)), half(65504.0))) * _805) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1038) * half(_1038)) / fast::max(_1024, 9.9999997473787516355514526367188e-05)) * half(_1057)) * half(_1057)), float3(65504.0))) * _1118), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1469 * (_1469 * (half(6.283185482025146484375) * _1462)), half(65504.0))) * _805) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1286) * half(_1286)) / fast::max(_1272, 9.9999997473787516355514526367188e-05)) * half(_1305)) * half(_1305)), float3(65504.0))) * _1366), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1481, half(1.0)));
    return out;
}

