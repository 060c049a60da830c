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
    half3 _577 = normalize(half3(in.v_normal));
    float3 _593 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _767 = max(dot(_577, half3(_593)), half(9.9999997473787516355514526367188e-05));
    float4 _806 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_767, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _825 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_806).y) - half(1.0)));
    float4 _832 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_593), _577)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _630 = half4(frame.lightDirection).xyz;
    half3 _939 = normalize(half3(_593) + _630);
    half _890 = clamp(dot(_577, _630), half(0.0), half(1.0));
    half3 _1002 = cross(_577, _939) * half(64.0);
    half _1005 = half(64.0) * half(params.facet_alpha);
    half _1006 = clamp(dot(_577, _939), half(0.0), half(1.0)) * _1005;
    half _982 = half(4096.0) * half(params.facet_alpha);
    half _985 = half(6.283185482025146484375) * max(mix((half(2.0) * _890) * _767, _890 + _767, half(params.facet_alpha)), half(0.000244140625));
    half _987 = _982 / (fma(_1006, _1006, dot(_1002, _1002)) * _985);
    float3 _1054 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1057 = dot(_1054, _1054);
    float3 _1062 = _1054 * rsqrt(fast::max(_1057, 9.9999999392252902907785028219223e-09));
    float _1066 = _1057 * float(frame.punctualLights[0].positionFalloff.w);
    float _1071 = fast::clamp(fma(-_1066, _1066, 1.0), 0.0, 1.0);
    float _1090 = fast::clamp(fma(dot(-_1062, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1200 = normalize(half3(_593) + half3(_1062));
    half _1151 = clamp(dot(_577, half3(_1062)), half(0.0), half(1.0));
    half3 _1263 = cross(_577, _1200) * half(64.0);
    half _1267 = clamp(dot(_577, _1200), half(0.0), half(1.0)) * _1005;
    half _1246 = half(6.283185482025146484375) * max(mix((half(2.0) * _1151) * _767, _1151 + _767, half(params.facet_alpha)), half(0.000244140625));
    half _1248 = _982 / (fma(_1267, _1267, dot(_1263, _1263)) * _1246);
    float3 _1315 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1318 = dot(_1315, _1315);
    float3 _1323 = _1315 * rsqrt(fast::max(_1318, 9.9999999392252902907785028219223e-09));
    float _1327 = _1318 * float(frame.punctualLights[1].positionFalloff.w);
    float _1332 = fast::clamp(fma(-_1327, _1327, 1.0), 0.0, 1.0);
    float _1351 = fast::clamp(fma(dot(-_1323, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1461 = normalize(half3(_593) + half3(_1323));
    half _1412 = clamp(dot(_577, half3(_1323)), half(0.0), half(1.0));
    half3 _1524 = cross(_577, _1461) * half(64.0);
    half _1528 = clamp(dot(_577, _1461), half(0.0), half(1.0)) * _1005;
    half _1507 = half(6.283185482025146484375) * max(mix((half(2.0) * _1412) * _767, _1412 + _767, half(params.facet_alpha)), half(0.000244140625));
    half _1509 = _982 / (fma(_1528, _1528, dot(_1524, _1524)) * _1507);
    half3 _1540 = (fma(half4(_832).xyz, mix(half4(_806).xxx, half4(_806).yyy, half3(float3(params.facet_f0))) * _825, min(((half3(float3(params.facet_f0)) * min(_987 * (_987 * _985), half(65504.0))) * _825) * (half4(frame.lightColor).xyz * _890), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1248 * (_1248 * _1246), half(65504.0))) * _825) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1071) * half(_1071)) / fast::max(_1057, 9.9999997473787516355514526367188e-05)) * half(_1090)) * half(_1090)), float3(65504.0))) * _1151), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1509 * (_1509 * _1507), half(65504.0))) * _825) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1332) * half(_1332)) / fast::max(_1318, 9.9999997473787516355514526367188e-05)) * half(_1351)) * half(_1351)), float3(65504.0))) * _1412), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1540, half(1.0)));
    return out;
}

