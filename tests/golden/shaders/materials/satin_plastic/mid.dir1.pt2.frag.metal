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
    half _953 = max(dot(_756, half3(_772)), half(9.9999997473787516355514526367188e-05));
    half3 _957 = reflect(-half3(_772), _756);
    float4 _992 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_953, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1011 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_992).y) - half(1.0)));
    float4 _1018 = facet_environment.sample(facet_environmentSmplr, float3(_957), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1095 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1052 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_953, _1095)), level(0.0));
    half3 _1102 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2168 = half4(_1052);
    half _1065 = _2168.z;
    half _1067 = fma(half(-float(max(_1102.x, max(_1102.y, _1102.z)))), _1065, half(1.0));
    half _1111 = _1095 * _1095;
    half4 _2172 = half4(_1052);
    half _1072 = _2172.w;
    float4 _1123 = facet_environment.sample(facet_environmentSmplr, float3(_957), level(_1095 * half(4.0)));
    half3 _818 = half4(frame.lightDirection).xyz;
    half3 _830 = half4(frame.lightColor).xyz;
    half3 _1239 = normalize(half3(_772) + _818);
    half _1178 = clamp(dot(_756, _818), half(0.0), half(1.0));
    half _1182 = clamp(dot(_756, _1239), half(0.0), half(1.0));
    half3 _1266 = cross(_756, _1239);
    half _1269 = _1182 * half(params.facet_alpha);
    half _1283 = _1178 + _953;
    half _1286 = max(mix((half(2.0) * _1178) * _953, _1283, half(params.facet_alpha)), half(0.000244140625));
    half _1288 = half(1024.0) * half(params.facet_alpha);
    half _1293 = _1288 / (fma(_1269, _1269, dot(_1266, _1266)) * (half(6433.98193359375) * _1286));
    half _1330 = half(8192.0) * fma(half(-float(_1178)), _953, _1283);
    half _1334 = half(1.0) / (_1111 * _1330);
    half _1341 = half(2048.0) * _1111;
    float3 _1399 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1402 = dot(_1399, _1399);
    float3 _1407 = _1399 * rsqrt(fast::max(_1402, 9.9999999392252902907785028219223e-09));
    float _1411 = _1402 * float(frame.punctualLights[0].positionFalloff.w);
    float _1416 = fast::clamp(fma(-_1411, _1411, 1.0), 0.0, 1.0);
    float _1435 = fast::clamp(fma(dot(-_1407, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1446 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1416) * half(_1416)) / fast::max(_1402, 9.9999997473787516355514526367188e-05)) * half(_1435)) * half(_1435)), float3(65504.0));
    half3 _1562 = normalize(half3(_772) + half3(_1407));
    half _1501 = clamp(dot(_756, half3(_1407)), half(0.0), half(1.0));
    half _1505 = clamp(dot(_756, _1562), half(0.0), half(1.0));
    half3 _1589 = cross(_756, _1562);
    half _1592 = _1505 * half(params.facet_alpha);
    half _1606 = _1501 + _953;
    half _1609 = max(mix((half(2.0) * _1501) * _953, _1606, half(params.facet_alpha)), half(0.000244140625));
    half _1616 = _1288 / (fma(_1592, _1592, dot(_1589, _1589)) * (half(6433.98193359375) * _1609));
    half _1653 = half(8192.0) * fma(half(-float(_1501)), _953, _1606);
    half _1657 = half(1.0) / (_1111 * _1653);
    half3 _1686 = (fma(half4(_1123).xyz, _1102 * _1065, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1018).xyz * (mix(half4(_992).xxx, half4(_992).yyy, half3(float3(params.facet_f0))) * _1011)) * _1067) + min(fma((half3(float3(params.facet_f0)) * min(_1293 * (_1293 * (half(6.283185482025146484375) * _1286)), half(65504.0))) * _1011, (_830 * _1178) * _1067, (_1102 * ((((fma(_1334, _1330, half(2.0)) * pow(max(fma(half(-float(_1182)), _1182, half(1.0)), half(0.0)), half(0.5) * (_1334 * _1330))) * half(0.15915493667125701904296875)) * (_1178 * (_1334 * _1341))) * _1072)) * _830), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1616 * (_1616 * (half(6.283185482025146484375) * _1609)), half(65504.0))) * _1011, (half3(_1446) * _1501) * _1067, (_1102 * ((((fma(_1657, _1653, half(2.0)) * pow(max(fma(half(-float(_1505)), _1505, half(1.0)), half(0.0)), half(0.5) * (_1657 * _1653))) * half(0.15915493667125701904296875)) * (_1501 * (_1657 * _1341))) * _1072)) * half3(_1446)), half3(float3(65504.0)));
    float3 _1722 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1725 = dot(_1722, _1722);
    float3 _1730 = _1722 * rsqrt(fast::max(_1725, 9.9999999392252902907785028219223e-09));
    float _1734 = _1725 * float(frame.punctualLights[1].positionFalloff.w);
    float _1739 = fast::clamp(fma(-_1734, _1734, 1.0), 0.0, 1.0);
    float _1758 = fast::clamp(fma(dot(-_1730, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1769 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1739) * half(_1739)) / fast::max(_1725, 9.9999997473787516355514526367188e-05)) * half(_1758)) * half(_1758)), float3(65504.0));
    half3 _1885 = normalize(half3(_772) + half3(_1730));
    half _1824 = clamp(dot(_756, half3(_1730)), half(0.0), half(1.0));
    half _1828 = clamp(dot(_756, _1885), half(0.0), half(1.0));
    half3 _1912 = cross(_756, _1885);
    half _1915 = _1828 * half(params.facet_alpha);
    half _1929 = _1824 + _953;
    half _1932 = max(mix((half(2.0) * _1824) * _953, _1929, half(params.facet_alpha)), half(0.000244140625));
    half _1939 = _1288 / (fma(_1915, _1915, dot(_1912, _1912)) * (half(6433.98193359375) * _1932));
    half _1976 = half(8192.0) * fma(half(-float(_1824)), _953, _1929);
    half _1980 = half(1.0) / (_1111 * _1976);
    out.fragColor = float4(half4(_1686 + min(fma((half3(float3(params.facet_f0)) * min(_1939 * (_1939 * (half(6.283185482025146484375) * _1932)), half(65504.0))) * _1011, (half3(_1769) * _1824) * _1067, (_1102 * ((((fma(_1980, _1976, half(2.0)) * pow(max(fma(half(-float(_1828)), _1828, half(1.0)), half(0.0)), half(0.5) * (_1980 * _1976))) * half(0.15915493667125701904296875)) * (_1824 * (_1980 * _1341))) * _1072)) * half3(_1769)), half3(float3(65504.0))), half(1.0)));
    return out;
}

