#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
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
    half3 _649 = normalize(half3(in.v_normal));
    float3 _665 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _834 = max(dot(_649, half3(_665)), half(9.9999997473787516355514526367188e-05));
    half3 _838 = reflect(-half3(_665), _649);
    float4 _873 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_834, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _892 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_873).y) - half(1.0)));
    float4 _899 = facet_environment.sample(facet_environmentSmplr, float3(_838), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _944 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _947 = dot(_944, _944);
    float3 _952 = _944 * rsqrt(fast::max(_947, 9.9999999392252902907785028219223e-09));
    float _956 = _947 * float(frame.punctualLights[0].positionFalloff.w);
    float _961 = fast::clamp(fma(-_956, _956, 1.0), 0.0, 1.0);
    float _980 = fast::clamp(fma(dot(-_952, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1090 = normalize(half3(_665) + half3(_952));
    half _1041 = clamp(dot(_649, half3(_952)), half(0.0), half(1.0));
    half3 _1117 = cross(_649, _1090);
    half _1120 = clamp(dot(_649, _1090), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1137 = max(mix((half(2.0) * _1041) * _834, _1041 + _834, half(params.facet_alpha)), half(0.000244140625));
    half _1139 = half(1024.0) * half(params.facet_alpha);
    half _1144 = _1139 / (fma(_1120, _1120, dot(_1117, _1117)) * (half(6433.98193359375) * _1137));
    float3 _1192 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1195 = dot(_1192, _1192);
    float3 _1200 = _1192 * rsqrt(fast::max(_1195, 9.9999999392252902907785028219223e-09));
    float _1204 = _1195 * float(frame.punctualLights[1].positionFalloff.w);
    float _1209 = fast::clamp(fma(-_1204, _1204, 1.0), 0.0, 1.0);
    float _1228 = fast::clamp(fma(dot(-_1200, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1338 = normalize(half3(_665) + half3(_1200));
    half _1289 = clamp(dot(_649, half3(_1200)), half(0.0), half(1.0));
    half3 _1365 = cross(_649, _1338);
    half _1368 = clamp(dot(_649, _1338), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1385 = max(mix((half(2.0) * _1289) * _834, _1289 + _834, half(params.facet_alpha)), half(0.000244140625));
    half _1392 = _1139 / (fma(_1368, _1368, dot(_1365, _1365)) * (half(6433.98193359375) * _1385));
    half _1443 = half(1.0) - _834;
    half _1446 = _1443 * _1443;
    float4 _1470 = facet_environment.sample(facet_environmentSmplr, float3(_838), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1437 = mix(fma(half4(_899).xyz, mix(half4(_873).xxx, half4(_873).yyy, half3(float3(params.facet_f0))) * _892, min(((half3(float3(params.facet_f0)) * min(_1144 * (_1144 * (half(6.283185482025146484375) * _1137)), half(65504.0))) * _892) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_961) * half(_961)) / fast::max(_947, 9.9999997473787516355514526367188e-05)) * half(_980)) * half(_980)), float3(65504.0))) * _1041), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1392 * (_1392 * (half(6.283185482025146484375) * _1385)), half(65504.0))) * _892) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1209) * half(_1209)) / fast::max(_1195, 9.9999997473787516355514526367188e-05)) * half(_1228)) * half(_1228)), float3(65504.0))) * _1289), half3(float3(65504.0))), half4(_1470).xyz, half3(fma(half(0.959999978542327880859375), (_1446 * _1446) * _1443, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1437, half(1.0)));
    return out;
}

