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
    half3 _739 = normalize(half3(in.v_normal));
    float3 _755 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _939 = max(dot(_739, half3(_755)), half(9.9999997473787516355514526367188e-05));
    half3 _943 = reflect(-half3(_755), _739);
    float4 _979 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_939, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1005 = facet_environment.sample(facet_environmentSmplr, float3(_943), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _958 = mix(half4(_979).xxx, half4(_979).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_979).y) - half(1.0))));
    half _1082 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1039 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_939, _1082)), level(0.0));
    half3 _1089 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2095 = half4(_1039);
    half _1052 = _2095.z;
    half _1054 = fma(half(-float(max(_1089.x, max(_1089.y, _1089.z)))), _1052, half(1.0));
    half _1098 = _1082 * _1082;
    half4 _2099 = half4(_1039);
    half _1059 = _2099.w;
    float4 _1110 = facet_environment.sample(facet_environmentSmplr, float3(_943), level(_1082 * half(4.0)));
    half3 _801 = half4(frame.lightDirection).xyz;
    half3 _813 = half4(frame.lightColor).xyz;
    half _1165 = clamp(dot(_739, _801), half(0.0), half(1.0));
    half _1169 = clamp(dot(_739, normalize(half3(_755) + _801)), half(0.0), half(1.0));
    half _1248 = clamp(dot(_943, _801), half(0.0), half(1.0));
    half _1251 = _1248 * _1248;
    half4 _2117 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1251 * _1251, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1263 = _2117.x;
    half _1297 = half(8192.0) * fma(half(-float(_1165)), _939, _1165 + _939);
    half _1301 = half(1.0) / (_1098 * _1297);
    half _1308 = half(2048.0) * _1098;
    float3 _1366 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1369 = dot(_1366, _1366);
    float3 _1374 = _1366 * rsqrt(fast::max(_1369, 9.9999999392252902907785028219223e-09));
    float _1378 = _1369 * float(frame.punctualLights[0].positionFalloff.w);
    float _1383 = fast::clamp(fma(-_1378, _1378, 1.0), 0.0, 1.0);
    float _1402 = fast::clamp(fma(dot(-_1374, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1413 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1383) * half(_1383)) / fast::max(_1369, 9.9999997473787516355514526367188e-05)) * half(_1402)) * half(_1402)), float3(65504.0));
    half _1468 = clamp(dot(_739, half3(_1374)), half(0.0), half(1.0));
    half _1472 = clamp(dot(_739, normalize(half3(_755) + half3(_1374))), half(0.0), half(1.0));
    half _1551 = clamp(dot(_943, half3(_1374)), half(0.0), half(1.0));
    half _1554 = _1551 * _1551;
    half4 _2158 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1554 * _1554, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1566 = _2158.x;
    half _1600 = half(8192.0) * fma(half(-float(_1468)), _939, _1468 + _939);
    half _1604 = half(1.0) / (_1098 * _1600);
    float3 _1669 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1672 = dot(_1669, _1669);
    float3 _1677 = _1669 * rsqrt(fast::max(_1672, 9.9999999392252902907785028219223e-09));
    float _1681 = _1672 * float(frame.punctualLights[1].positionFalloff.w);
    float _1686 = fast::clamp(fma(-_1681, _1681, 1.0), 0.0, 1.0);
    float _1705 = fast::clamp(fma(dot(-_1677, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1716 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1686) * half(_1686)) / fast::max(_1672, 9.9999997473787516355514526367188e-05)) * half(_1705)) * half(_1705)), float3(65504.0));
    half _1771 = clamp(dot(_739, half3(_1677)), half(0.0), half(1.0));
    half _1775 = clamp(dot(_739, normalize(half3(_755) + half3(_1677))), half(0.0), half(1.0));
    half _1854 = clamp(dot(_943, half3(_1677)), half(0.0), half(1.0));
    half _1857 = _1854 * _1854;
    half4 _2200 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1857 * _1857, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1869 = _2200.x;
    half _1903 = half(8192.0) * fma(half(-float(_1771)), _939, _1771 + _939);
    half _1907 = half(1.0) / (_1098 * _1903);
    half3 _1936 = ((fma(half4(_1110).xyz, _1089 * _1052, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1005).xyz * _958) * _1054) + min(fma(_958 * ((_1263 * _1263) * half(5.092957973480224609375)), (_813 * _1165) * _1054, (_1089 * ((((fma(_1301, _1297, half(2.0)) * pow(max(fma(half(-float(_1169)), _1169, half(1.0)), half(0.0)), half(0.5) * (_1301 * _1297))) * half(0.15915493667125701904296875)) * (_1165 * (_1301 * _1308))) * _1059)) * _813), half3(float3(65504.0)))) + min(fma(_958 * ((_1566 * _1566) * half(5.092957973480224609375)), (half3(_1413) * _1468) * _1054, (_1089 * ((((fma(_1604, _1600, half(2.0)) * pow(max(fma(half(-float(_1472)), _1472, half(1.0)), half(0.0)), half(0.5) * (_1604 * _1600))) * half(0.15915493667125701904296875)) * (_1468 * (_1604 * _1308))) * _1059)) * half3(_1413)), half3(float3(65504.0)))) + min(fma(_958 * ((_1869 * _1869) * half(5.092957973480224609375)), (half3(_1716) * _1771) * _1054, (_1089 * ((((fma(_1907, _1903, half(2.0)) * pow(max(fma(half(-float(_1775)), _1775, half(1.0)), half(0.0)), half(0.5) * (_1907 * _1903))) * half(0.15915493667125701904296875)) * (_1771 * (_1907 * _1308))) * _1059)) * half3(_1716)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1936, half(1.0)));
    return out;
}

