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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _841 = normalize(half3(in.v_normal));
    float3 _847 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1062 = max(dot(_841, half3(_847)), half(9.9999997473787516355514526367188e-05));
    half3 _1066 = reflect(-half3(_847), _841);
    float4 _1101 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1062, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1120 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1101).y) - half(1.0)));
    float4 _1130 = facet_environment.sample(facet_environmentSmplr, float3(_1066), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1177 = half(1.0) - _1062;
    half _1180 = _1177 * _1177;
    half _1187 = fma(half(0.959999978542327880859375), (_1180 * _1180) * _1177, half(0.039999999105930328369140625));
    half _1157 = fma(half(-float(_1187)), half(params.facet_clearCoat), half(1.0));
    float4 _1165 = facet_environment.sample(facet_environmentSmplr, float3(_1066), level(params.facet_clearCoatLod));
    float3 _1227 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1230 = dot(_1227, _1227);
    float3 _1235 = _1227 * rsqrt(fast::max(_1230, 9.9999999392252902907785028219223e-09));
    float _1239 = _1230 * float(frame.punctualLights[0].positionFalloff.w);
    float _1244 = fast::clamp(fma(-_1239, _1239, 1.0), 0.0, 1.0);
    float _1263 = fast::clamp(fma(dot(-_1235, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1398 = normalize(half3(_847) + half3(_1235));
    half _1331 = clamp(dot(_841, half3(_1235)), half(0.0), half(1.0));
    half _1335 = clamp(dot(_841, _1398), half(0.0), half(1.0));
    half _1339 = clamp(dot(half3(_1235), _1398), half(0.0), half(1.0));
    half3 _1461 = cross(_841, _1398) * half(64.0);
    half _1463 = half(64.0) * half(params.facet_alpha);
    half _1465 = _1463 * _1335;
    half _1468 = dot(_1461, _1461);
    half _1441 = half(4096.0) * half(params.facet_alpha);
    half _1444 = half(6.283185482025146484375) * max(mix((half(2.0) * _1331) * _1062, _1331 + _1062, half(params.facet_alpha)), half(0.000244140625));
    half _1446 = _1441 / (fma(_1465, _1465, _1468) * _1444);
    half _1553 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1555 = _1553 * _1335;
    half _1507 = half(12.56637096405029296875) * max(_1339 * _1339, half(6.103515625e-05));
    half _1509 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1513 = _1509 / (fma(_1555, _1555, _1468) * _1507);
    half _1523 = half(1.0) - _1339;
    half _1526 = _1523 * _1523;
    half _1531 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1621 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1624 = dot(_1621, _1621);
    float3 _1629 = _1621 * rsqrt(fast::max(_1624, 9.9999999392252902907785028219223e-09));
    float _1633 = _1624 * float(frame.punctualLights[1].positionFalloff.w);
    float _1638 = fast::clamp(fma(-_1633, _1633, 1.0), 0.0, 1.0);
    float _1657 = fast::clamp(fma(dot(-_1629, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1792 = normalize(half3(_847) + half3(_1629));
    half _1725 = clamp(dot(_841, half3(_1629)), half(0.0), half(1.0));
    half _1729 = clamp(dot(_841, _1792), half(0.0), half(1.0));
    half _1733 = clamp(dot(half3(_1629), _1792), half(0.0), half(1.0));
    half3 _1855 = cross(_841, _1792) * half(64.0);
    half _1859 = _1463 * _1729;
    half _1862 = dot(_1855, _1855);
    half _1838 = half(6.283185482025146484375) * max(mix((half(2.0) * _1725) * _1062, _1725 + _1062, half(params.facet_alpha)), half(0.000244140625));
    half _1840 = _1441 / (fma(_1859, _1859, _1862) * _1838);
    half _1949 = _1553 * _1729;
    half _1901 = half(12.56637096405029296875) * max(_1733 * _1733, half(6.103515625e-05));
    half _1907 = _1509 / (fma(_1949, _1949, _1862) * _1901);
    half _1917 = half(1.0) - _1733;
    half _1920 = _1917 * _1917;
    half3 _1979 = (mix(half4(_1130).xyz * (mix(half4(_1101).xxx, half4(_1101).yyy, half3(float3(params.facet_f0))) * _1120), half4(_1165).xyz, half3(_1187 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1446 * (_1446 * _1444), half(65504.0))) * _1120) * _1157) + half3(min(_1513 * (_1513 * _1507), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1531 * ((_1526 * _1526) * _1523))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1244) * half(_1244)) / fast::max(_1230, 9.9999997473787516355514526367188e-05)) * half(_1263)) * half(_1263)), float3(65504.0))) * _1331), half3(float3(65504.0)))) + min(min((((half3(float3(params.facet_f0)) * min(_1840 * (_1840 * _1838), half(65504.0))) * _1120) * _1157) + half3(min(_1907 * (_1907 * _1901), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1531 * ((_1920 * _1920) * _1917))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1638) * half(_1638)) / fast::max(_1624, 9.9999997473787516355514526367188e-05)) * half(_1657)) * half(_1657)), float3(65504.0))) * _1725), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1979, half(1.0)));
    return out;
}

