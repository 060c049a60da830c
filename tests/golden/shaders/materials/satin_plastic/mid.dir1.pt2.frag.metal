#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _744 = normalize(half3(in.v_normal));
    float3 _760 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _940 = max(dot(_744, half3(_760)), half(9.9999997473787516355514526367188e-05));
    half3 _944 = reflect(-half3(_760), _744);
    float4 _973 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_940, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _992 = facet_environment.sample(facet_environmentSmplr, float3(_944), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1024 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_940, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2133 = half4(_1024);
    half _1037 = _2133.z;
    half _1039 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1037, half(1.0));
    half4 _2137 = half4(_1024);
    half _1044 = _2137.w;
    float4 _1053 = facet_environment.sample(facet_environmentSmplr, float3(_944), level(params.facet_sheenLod));
    half3 _806 = half4(frame.lightDirection).xyz;
    half3 _818 = half4(frame.lightColor).xyz;
    half3 _1189 = normalize(half3(_760) + _806);
    half _1131 = clamp(dot(_744, _806), half(0.0), half(1.0));
    half _1135 = clamp(dot(_744, _1189), half(0.0), half(1.0));
    half4 _1258 = half4(cross(_744, _1189), half(params.facet_alpha) * _1135) * half(64.0);
    half _1227 = _1131 + _940;
    half _1232 = half(4096.0) * half(params.facet_alpha);
    half _1235 = half(6.283185482025146484375) * max(mix((half(2.0) * _1131) * _940, _1227, half(params.facet_alpha)), half(0.000244140625));
    half _1237 = _1232 / (dot(_1258, _1258) * _1235);
    half _1291 = half(8192.0) * fma(half(-float(_1131)), _940, _1227);
    half _1295 = half(1.0) / (half(params.facet_sheenAlpha) * _1291);
    half _1302 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1360 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1363 = dot(_1360, _1360);
    float3 _1368 = _1360 * rsqrt(fast::max(_1363, 9.9999999392252902907785028219223e-09));
    float _1372 = _1363 * float(frame.punctualLights[0].positionFalloff.w);
    float _1377 = fast::clamp(fma(-_1372, _1372, 1.0), 0.0, 1.0);
    float _1396 = fast::clamp(fma(dot(-_1368, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1407 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1377) * half(_1377)) / fast::max(_1363, 9.9999997473787516355514526367188e-05)) * half(_1396)) * half(_1396)), float3(65504.0));
    half3 _1520 = normalize(half3(_760) + half3(_1368));
    half _1462 = clamp(dot(_744, half3(_1368)), half(0.0), half(1.0));
    half _1466 = clamp(dot(_744, _1520), half(0.0), half(1.0));
    half4 _1589 = half4(cross(_744, _1520), half(params.facet_alpha) * _1466) * half(64.0);
    half _1558 = _1462 + _940;
    half _1566 = half(6.283185482025146484375) * max(mix((half(2.0) * _1462) * _940, _1558, half(params.facet_alpha)), half(0.000244140625));
    half _1568 = _1232 / (dot(_1589, _1589) * _1566);
    half _1622 = half(8192.0) * fma(half(-float(_1462)), _940, _1558);
    half _1626 = half(1.0) / (half(params.facet_sheenAlpha) * _1622);
    half3 _1655 = (fma(half4(_1053).xyz, half3(float3(params.facet_sheenColor)) * _1037, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_992).xyz * mix(half4(_973).xxx, half4(_973).yyy, half3(float3(params.facet_f0)))) * _1039) + min(fma(half3(float3(params.facet_f0)) * min(_1237 * (_1237 * _1235), half(65504.0)), (_818 * _1131) * _1039, (half3(float3(params.facet_sheenColor)) * ((((fma(_1295, _1291, half(2.0)) * pow(max(fma(half(-float(_1135)), _1135, half(1.0)), half(0.0)), half(0.5) * (_1295 * _1291))) * half(0.15915493667125701904296875)) * (_1131 * (_1295 * _1302))) * _1044)) * _818), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min(_1568 * (_1568 * _1566), half(65504.0)), (half3(_1407) * _1462) * _1039, (half3(float3(params.facet_sheenColor)) * ((((fma(_1626, _1622, half(2.0)) * pow(max(fma(half(-float(_1466)), _1466, half(1.0)), half(0.0)), half(0.5) * (_1626 * _1622))) * half(0.15915493667125701904296875)) * (_1462 * (_1626 * _1302))) * _1044)) * half3(_1407)), half3(float3(65504.0)));
    float3 _1691 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1694 = dot(_1691, _1691);
    float3 _1699 = _1691 * rsqrt(fast::max(_1694, 9.9999999392252902907785028219223e-09));
    float _1703 = _1694 * float(frame.punctualLights[1].positionFalloff.w);
    float _1708 = fast::clamp(fma(-_1703, _1703, 1.0), 0.0, 1.0);
    float _1727 = fast::clamp(fma(dot(-_1699, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1738 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1708) * half(_1708)) / fast::max(_1694, 9.9999997473787516355514526367188e-05)) * half(_1727)) * half(_1727)), float3(65504.0));
    half3 _1851 = normalize(half3(_760) + half3(_1699));
    half _1793 = clamp(dot(_744, half3(_1699)), half(0.0), half(1.0));
    half _1797 = clamp(dot(_744, _1851), half(0.0), half(1.0));
    half4 _1920 = half4(cross(_744, _1851), half(params.facet_alpha) * _1797) * half(64.0);
    half _1889 = _1793 + _940;
    half _1897 = half(6.283185482025146484375) * max(mix((half(2.0) * _1793) * _940, _1889, half(params.facet_alpha)), half(0.000244140625));
    half _1899 = _1232 / (dot(_1920, _1920) * _1897);
    half _1953 = half(8192.0) * fma(half(-float(_1793)), _940, _1889);
    half _1957 = half(1.0) / (half(params.facet_sheenAlpha) * _1953);
    out.fragColor = float4(half4(_1655 + min(fma(half3(float3(params.facet_f0)) * min(_1899 * (_1899 * _1897), half(65504.0)), (half3(_1738) * _1793) * _1039, (half3(float3(params.facet_sheenColor)) * ((((fma(_1957, _1953, half(2.0)) * pow(max(fma(half(-float(_1797)), _1797, half(1.0)), half(0.0)), half(0.5) * (_1957 * _1953))) * half(0.15915493667125701904296875)) * (_1793 * (_1957 * _1302))) * _1044)) * half3(_1738)), half3(float3(65504.0))), half(1.0)));
    return out;
}

