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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _742 = normalize(half3(in.v_normal));
    float3 _758 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _942 = max(dot(_742, half3(_758)), half(9.9999997473787516355514526367188e-05));
    half3 _946 = reflect(-half3(_758), _742);
    float4 _982 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_942, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1011 = facet_environment.sample(facet_environmentSmplr, float3(_946), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _961 = mix(half4(_982).xxx, half4(_982).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_982).y) - half(1.0))));
    half _1088 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1045 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_942, _1088)), level(0.0));
    half3 _1095 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2106 = half4(_1045);
    half _1058 = _2106.z;
    half _1060 = fma(half(-float(max(_1095.x, max(_1095.y, _1095.z)))), _1058, half(1.0));
    half _1104 = _1088 * _1088;
    half4 _2110 = half4(_1045);
    half _1065 = _2110.w;
    float4 _1119 = facet_environment.sample(facet_environmentSmplr, float3(_946), level(_1088 * (half(4.0) * (half(2.0) - _1088))));
    half3 _804 = half4(frame.lightDirection).xyz;
    half3 _816 = half4(frame.lightColor).xyz;
    half _1174 = clamp(dot(_742, _804), half(0.0), half(1.0));
    half _1178 = clamp(dot(_742, normalize(half3(_758) + _804)), half(0.0), half(1.0));
    half _1257 = clamp(dot(_946, _804), half(0.0), half(1.0));
    half _1260 = _1257 * _1257;
    half4 _2129 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1260 * _1260, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1272 = _2129.x;
    half _1306 = half(8192.0) * fma(half(-float(_1174)), _942, _1174 + _942);
    half _1310 = half(1.0) / (_1104 * _1306);
    half _1317 = half(2048.0) * _1104;
    float3 _1375 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1378 = dot(_1375, _1375);
    float3 _1383 = _1375 * rsqrt(fast::max(_1378, 9.9999999392252902907785028219223e-09));
    float _1387 = _1378 * float(frame.punctualLights[0].positionFalloff.w);
    float _1392 = fast::clamp(fma(-_1387, _1387, 1.0), 0.0, 1.0);
    float _1411 = fast::clamp(fma(dot(-_1383, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1422 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1392) * half(_1392)) / fast::max(_1378, 9.9999997473787516355514526367188e-05)) * half(_1411)) * half(_1411)), float3(65504.0));
    half _1477 = clamp(dot(_742, half3(_1383)), half(0.0), half(1.0));
    half _1481 = clamp(dot(_742, normalize(half3(_758) + half3(_1383))), half(0.0), half(1.0));
    half _1560 = clamp(dot(_946, half3(_1383)), half(0.0), half(1.0));
    half _1563 = _1560 * _1560;
    half4 _2170 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1563 * _1563, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1575 = _2170.x;
    half _1609 = half(8192.0) * fma(half(-float(_1477)), _942, _1477 + _942);
    half _1613 = half(1.0) / (_1104 * _1609);
    float3 _1678 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1681 = dot(_1678, _1678);
    float3 _1686 = _1678 * rsqrt(fast::max(_1681, 9.9999999392252902907785028219223e-09));
    float _1690 = _1681 * float(frame.punctualLights[1].positionFalloff.w);
    float _1695 = fast::clamp(fma(-_1690, _1690, 1.0), 0.0, 1.0);
    float _1714 = fast::clamp(fma(dot(-_1686, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1725 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1695) * half(_1695)) / fast::max(_1681, 9.9999997473787516355514526367188e-05)) * half(_1714)) * half(_1714)), float3(65504.0));
    half _1780 = clamp(dot(_742, half3(_1686)), half(0.0), half(1.0));
    half _1784 = clamp(dot(_742, normalize(half3(_758) + half3(_1686))), half(0.0), half(1.0));
    half _1863 = clamp(dot(_946, half3(_1686)), half(0.0), half(1.0));
    half _1866 = _1863 * _1863;
    half4 _2212 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1866 * _1866, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1878 = _2212.x;
    half _1912 = half(8192.0) * fma(half(-float(_1780)), _942, _1780 + _942);
    half _1916 = half(1.0) / (_1104 * _1912);
    half3 _1945 = ((fma(half4(_1119).xyz, _1095 * _1058, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1011).xyz * _961) * _1060) + min(fma(_961 * ((_1272 * _1272) * half(5.092957973480224609375)), (_816 * _1174) * _1060, (_1095 * ((((fma(_1310, _1306, half(2.0)) * pow(max(fma(half(-float(_1178)), _1178, half(1.0)), half(0.0)), half(0.5) * (_1310 * _1306))) * half(0.15915493667125701904296875)) * (_1174 * (_1310 * _1317))) * _1065)) * _816), half3(float3(65504.0)))) + min(fma(_961 * ((_1575 * _1575) * half(5.092957973480224609375)), (half3(_1422) * _1477) * _1060, (_1095 * ((((fma(_1613, _1609, half(2.0)) * pow(max(fma(half(-float(_1481)), _1481, half(1.0)), half(0.0)), half(0.5) * (_1613 * _1609))) * half(0.15915493667125701904296875)) * (_1477 * (_1613 * _1317))) * _1065)) * half3(_1422)), half3(float3(65504.0)))) + min(fma(_961 * ((_1878 * _1878) * half(5.092957973480224609375)), (half3(_1725) * _1780) * _1060, (_1095 * ((((fma(_1916, _1912, half(2.0)) * pow(max(fma(half(-float(_1784)), _1784, half(1.0)), half(0.0)), half(0.5) * (_1916 * _1912))) * half(0.15915493667125701904296875)) * (_1780 * (_1916 * _1317))) * _1065)) * half3(_1725)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1945, half(1.0)));
    return out;
}

