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
    half3 _803 = normalize(half3(in.v_normal));
    float3 _819 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _979 = max(dot(_803, half3(_819)), half(9.9999997473787516355514526367188e-05));
    half3 _983 = reflect(-half3(_819), _803);
    float4 _1018 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_979, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1037 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1018).y) - half(1.0)));
    float4 _1044 = facet_environment.sample(facet_environmentSmplr, float3(_983), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1117 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1077 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_979, _1117)), level(0.0));
    half3 _1124 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2097 = half4(_1077);
    half _1090 = _2097.z;
    half _1092 = fma(half(-float(max(_1124.x, max(_1124.y, _1124.z)))), _1090, half(1.0));
    half4 _2101 = half4(_1077);
    half _1094 = _2101.w;
    float4 _1131 = facet_environment.sample(facet_environmentSmplr, float3(_983), level(_1117 * half(4.0)));
    float3 _1168 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1171 = dot(_1168, _1168);
    float3 _1176 = _1168 * rsqrt(fast::max(_1171, 9.9999999392252902907785028219223e-09));
    float _1180 = _1171 * float(frame.punctualLights[0].positionFalloff.w);
    float _1185 = fast::clamp(fma(-_1180, _1180, 1.0), 0.0, 1.0);
    float _1204 = fast::clamp(fma(dot(-_1176, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1215 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1185) * half(_1185)) / fast::max(_1171, 9.9999997473787516355514526367188e-05)) * half(_1204)) * half(_1204)), float3(65504.0));
    half3 _1346 = normalize(half3(_819) + half3(_1176));
    half _1294 = clamp(dot(_803, half3(_1176)), half(0.0), half(1.0));
    half _1298 = clamp(dot(_803, _1346), half(0.0), half(1.0));
    half3 _1373 = cross(_803, _1346);
    half _1376 = _1298 * half(params.facet_alpha);
    half _1390 = _1294 + _979;
    half _1393 = max(mix((half(2.0) * _1294) * _979, _1390, half(params.facet_alpha)), half(0.000244140625));
    half _1395 = half(1024.0) * half(params.facet_alpha);
    half _1400 = _1395 / (fma(_1376, _1376, dot(_1373, _1373)) * (half(6433.98193359375) * _1393));
    half _1468 = _1117 * _1117;
    half _1488 = half(8192.0) * fma(half(-float(_1294)), _979, _1390);
    half _1492 = half(1.0) / (_1468 * _1488);
    half _1499 = half(2048.0) * _1468;
    float3 _1569 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1572 = dot(_1569, _1569);
    float3 _1577 = _1569 * rsqrt(fast::max(_1572, 9.9999999392252902907785028219223e-09));
    float _1581 = _1572 * float(frame.punctualLights[1].positionFalloff.w);
    float _1586 = fast::clamp(fma(-_1581, _1581, 1.0), 0.0, 1.0);
    float _1605 = fast::clamp(fma(dot(-_1577, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1616 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1586) * half(_1586)) / fast::max(_1572, 9.9999997473787516355514526367188e-05)) * half(_1605)) * half(_1605)), float3(65504.0));
    half3 _1747 = normalize(half3(_819) + half3(_1577));
    half _1695 = clamp(dot(_803, half3(_1577)), half(0.0), half(1.0));
    half _1699 = clamp(dot(_803, _1747), half(0.0), half(1.0));
    half3 _1774 = cross(_803, _1747);
    half _1777 = _1699 * half(params.facet_alpha);
    half _1791 = _1695 + _979;
    half _1794 = max(mix((half(2.0) * _1695) * _979, _1791, half(params.facet_alpha)), half(0.000244140625));
    half _1801 = _1395 / (fma(_1777, _1777, dot(_1774, _1774)) * (half(6433.98193359375) * _1794));
    half _1889 = half(8192.0) * fma(half(-float(_1695)), _979, _1791);
    half _1893 = half(1.0) / (_1468 * _1889);
    half3 _1934 = (fma(half4(_1131).xyz, _1124 * _1090, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1044).xyz * (mix(half4(_1018).xxx, half4(_1018).yyy, half3(float3(params.facet_f0))) * _1037)) * _1092) + (min(((half3(float3(params.facet_f0)) * min(_1400 * (_1400 * (half(6.283185482025146484375) * _1393)), half(65504.0))) * _1037) * ((half3(_1215) * _1294) * _1092), half3(float3(65504.0))) + min((_1124 * ((((fma(_1492, _1488, half(2.0)) * pow(max(fma(half(-float(_1298)), _1298, half(1.0)), half(0.0)), half(0.5) * (_1492 * _1488))) * half(0.15915493667125701904296875)) * (_1294 * (_1492 * _1499))) * _1094)) * half3(_1215), half3(float3(65504.0))))) + (min(((half3(float3(params.facet_f0)) * min(_1801 * (_1801 * (half(6.283185482025146484375) * _1794)), half(65504.0))) * _1037) * ((half3(_1616) * _1695) * _1092), half3(float3(65504.0))) + min((_1124 * ((((fma(_1893, _1889, half(2.0)) * pow(max(fma(half(-float(_1699)), _1699, half(1.0)), half(0.0)), half(0.5) * (_1893 * _1889))) * half(0.15915493667125701904296875)) * (_1695 * (_1893 * _1499))) * _1094)) * half3(_1616), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1934, half(1.0)));
    return out;
}

