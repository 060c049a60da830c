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
    half _855 = max(dot(_649, half3(_665)), half(9.9999997473787516355514526367188e-05));
    half3 _859 = reflect(-half3(_665), _649);
    float4 _894 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_855, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _913 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_894).y) - half(1.0)));
    float4 _920 = facet_environment.sample(facet_environmentSmplr, float3(_859), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _703 = half4(frame.lightDirection).xyz;
    half3 _1027 = normalize(half3(_665) + _703);
    half _978 = clamp(dot(_649, _703), half(0.0), half(1.0));
    half3 _1054 = cross(_649, _1027);
    half _1057 = clamp(dot(_649, _1027), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1074 = max(mix((half(2.0) * _978) * _855, _978 + _855, half(params.facet_alpha)), half(0.000244140625));
    half _1076 = half(1024.0) * half(params.facet_alpha);
    half _1081 = _1076 / (fma(_1057, _1057, dot(_1054, _1054)) * (half(6433.98193359375) * _1074));
    float3 _1129 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1132 = dot(_1129, _1129);
    float3 _1137 = _1129 * rsqrt(fast::max(_1132, 9.9999999392252902907785028219223e-09));
    float _1141 = _1132 * float(frame.punctualLights[0].positionFalloff.w);
    float _1146 = fast::clamp(fma(-_1141, _1141, 1.0), 0.0, 1.0);
    float _1165 = fast::clamp(fma(dot(-_1137, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1275 = normalize(half3(_665) + half3(_1137));
    half _1226 = clamp(dot(_649, half3(_1137)), half(0.0), half(1.0));
    half3 _1302 = cross(_649, _1275);
    half _1305 = clamp(dot(_649, _1275), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1322 = max(mix((half(2.0) * _1226) * _855, _1226 + _855, half(params.facet_alpha)), half(0.000244140625));
    half _1329 = _1076 / (fma(_1305, _1305, dot(_1302, _1302)) * (half(6433.98193359375) * _1322));
    float3 _1377 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1380 = dot(_1377, _1377);
    float3 _1385 = _1377 * rsqrt(fast::max(_1380, 9.9999999392252902907785028219223e-09));
    float _1389 = _1380 * float(frame.punctualLights[1].positionFalloff.w);
    float _1394 = fast::clamp(fma(-_1389, _1389, 1.0), 0.0, 1.0);
    float _1413 = fast::clamp(fma(dot(-_1385, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1523 = normalize(half3(_665) + half3(_1385));
    half _1474 = clamp(dot(_649, half3(_1385)), half(0.0), half(1.0));
    half3 _1550 = cross(_649, _1523);
    half _1553 = clamp(dot(_649, _1523), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1570 = max(mix((half(2.0) * _1474) * _855, _1474 + _855, half(params.facet_alpha)), half(0.000244140625));
    half _1577 = _1076 / (fma(_1553, _1553, dot(_1550, _1550)) * (half(6433.98193359375) * _1570));
    half3 _1589 = (fma(half4(_920).xyz, mix(half4(_894).xxx, half4(_894).yyy, half3(float3(params.facet_f0))) * _913, min(((half3(float3(params.facet_f0)) * min(_1081 * (_1081 * (half(6.283185482025146484375) * _1074)), half(65504.0))) * _913) * (half4(frame.lightColor).xyz * _978), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1329 * (_1329 * (half(6.283185482025146484375) * _1322)), half(65504.0))) * _913) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1146) * half(_1146)) / fast::max(_1132, 9.9999997473787516355514526367188e-05)) * half(_1165)) * half(_1165)), float3(65504.0))) * _1226), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1577 * (_1577 * (half(6.283185482025146484375) * _1570)), half(65504.0))) * _913) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1394) * half(_1394)) / fast::max(_1380, 9.9999997473787516355514526367188e-05)) * half(_1413)) * half(_1413)), float3(65504.0))) * _1474), half3(float3(65504.0)));
    half _1628 = half(1.0) - _855;
    half _1631 = _1628 * _1628;
    float4 _1655 = facet_environment.sample(facet_environmentSmplr, float3(_859), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    out.fragColor = float4(half4(mix(_1589, half4(_1655).xyz, half3(fma(half(0.959999978542327880859375), (_1631 * _1631) * _1628, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

