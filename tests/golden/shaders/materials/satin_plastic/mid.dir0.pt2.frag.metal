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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _756 = normalize(half3(in.v_normal));
    float3 _772 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _932 = max(dot(_756, half3(_772)), half(9.9999997473787516355514526367188e-05));
    half3 _936 = reflect(-half3(_772), _756);
    float4 _971 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_932, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _990 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_971).y) - half(1.0)));
    float4 _997 = facet_environment.sample(facet_environmentSmplr, float3(_936), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1074 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1031 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_932, _1074)), level(0.0));
    half3 _1081 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1906 = half4(_1031);
    half _1044 = _1906.z;
    half _1046 = fma(half(-float(max(_1081.x, max(_1081.y, _1081.z)))), _1044, half(1.0));
    half _1090 = _1074 * _1074;
    half4 _1910 = half4(_1031);
    half _1051 = _1910.w;
    float4 _1102 = facet_environment.sample(facet_environmentSmplr, float3(_936), level(_1074 * half(4.0)));
    float3 _1139 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1142 = dot(_1139, _1139);
    float3 _1147 = _1139 * rsqrt(fast::max(_1142, 9.9999999392252902907785028219223e-09));
    float _1151 = _1142 * float(frame.punctualLights[0].positionFalloff.w);
    float _1156 = fast::clamp(fma(-_1151, _1151, 1.0), 0.0, 1.0);
    float _1175 = fast::clamp(fma(dot(-_1147, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1186 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1156) * half(_1156)) / fast::max(_1142, 9.9999997473787516355514526367188e-05)) * half(_1175)) * half(_1175)), float3(65504.0));
    half3 _1302 = normalize(half3(_772) + half3(_1147));
    half _1241 = clamp(dot(_756, half3(_1147)), half(0.0), half(1.0));
    half _1245 = clamp(dot(_756, _1302), half(0.0), half(1.0));
    half3 _1329 = cross(_756, _1302);
    half _1332 = _1245 * half(params.facet_alpha);
    half _1346 = _1241 + _932;
    half _1349 = max(mix((half(2.0) * _1241) * _932, _1346, half(params.facet_alpha)), half(0.000244140625));
    half _1351 = half(1024.0) * half(params.facet_alpha);
    half _1356 = _1351 / (fma(_1332, _1332, dot(_1329, _1329)) * (half(6433.98193359375) * _1349));
    half _1393 = half(8192.0) * fma(half(-float(_1241)), _932, _1346);
    half _1397 = half(1.0) / (_1090 * _1393);
    half _1404 = half(2048.0) * _1090;
    float3 _1462 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1465 = dot(_1462, _1462);
    float3 _1470 = _1462 * rsqrt(fast::max(_1465, 9.9999999392252902907785028219223e-09));
    float _1474 = _1465 * float(frame.punctualLights[1].positionFalloff.w);
    float _1479 = fast::clamp(fma(-_1474, _1474, 1.0), 0.0, 1.0);
    float _1498 = fast::clamp(fma(dot(-_1470, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1509 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1479) * half(_1479)) / fast::max(_1465, 9.9999997473787516355514526367188e-05)) * half(_1498)) * half(_1498)), float3(65504.0));
    half3 _1625 = normalize(half3(_772) + half3(_1470));
    half _1564 = clamp(dot(_756, half3(_1470)), half(0.0), half(1.0));
    half _1568 = clamp(dot(_756, _1625), half(0.0), half(1.0));
    half3 _1652 = cross(_756, _1625);
    half _1655 = _1568 * half(params.facet_alpha);
    half _1669 = _1564 + _932;
    half _1672 = max(mix((half(2.0) * _1564) * _932, _1669, half(params.facet_alpha)), half(0.000244140625));
    half _1679 = _1351 / (fma(_1655, _1655, dot(_1652, _1652)) * (half(6433.98193359375) * _1672));
    half _1716 = half(8192.0) * fma(half(-float(_1564)), _932, _1669);
    half _1720 = half(1.0) / (_1090 * _1716);
    half3 _1749 = (fma(half4(_1102).xyz, _1081 * _1044, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_997).xyz * (mix(half4(_971).xxx, half4(_971).yyy, half3(float3(params.facet_f0))) * _990)) * _1046) + min(fma((half3(float3(params.facet_f0)) * min(_1356 * (_1356 * (half(6.283185482025146484375) * _1349)), half(65504.0))) * _990, (half3(_1186) * _1241) * _1046, (_1081 * ((((fma(_1397, _1393, half(2.0)) * pow(max(fma(half(-float(_1245)), _1245, half(1.0)), half(0.0)), half(0.5) * (_1397 * _1393))) * half(0.15915493667125701904296875)) * (_1241 * (_1397 * _1404))) * _1051)) * half3(_1186)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1679 * (_1679 * (half(6.283185482025146484375) * _1672)), half(65504.0))) * _990, (half3(_1509) * _1564) * _1046, (_1081 * ((((fma(_1720, _1716, half(2.0)) * pow(max(fma(half(-float(_1568)), _1568, half(1.0)), half(0.0)), half(0.5) * (_1720 * _1716))) * half(0.15915493667125701904296875)) * (_1564 * (_1720 * _1404))) * _1051)) * half3(_1509)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1749, half(1.0)));
    return out;
}

