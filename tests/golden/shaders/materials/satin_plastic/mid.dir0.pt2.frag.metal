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
    half3 _777 = normalize(half3(in.v_normal));
    float3 _793 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _953 = max(dot(_777, half3(_793)), half(9.9999997473787516355514526367188e-05));
    half3 _957 = reflect(-half3(_793), _777);
    float4 _992 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_953, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1011 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_992).y) - half(1.0)));
    float4 _1021 = facet_environment.sample(facet_environmentSmplr, float3(_957), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1098 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1055 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_953, _1098)), level(0.0));
    half3 _1105 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1957 = half4(_1055);
    half _1068 = _1957.z;
    half _1070 = fma(half(-float(max(_1105.x, max(_1105.y, _1105.z)))), _1068, half(1.0));
    half _1114 = _1098 * _1098;
    half4 _1961 = half4(_1055);
    half _1075 = _1961.w;
    float4 _1129 = facet_environment.sample(facet_environmentSmplr, float3(_957), level(_1098 * (half(4.0) * (half(2.0) - _1098))));
    float3 _1166 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1169 = dot(_1166, _1166);
    float3 _1174 = _1166 * rsqrt(fast::max(_1169, 9.9999999392252902907785028219223e-09));
    float _1178 = _1169 * float(frame.punctualLights[0].positionFalloff.w);
    float _1183 = fast::clamp(fma(-_1178, _1178, 1.0), 0.0, 1.0);
    float _1202 = fast::clamp(fma(dot(-_1174, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1213 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1183) * half(_1183)) / fast::max(_1169, 9.9999997473787516355514526367188e-05)) * half(_1202)) * half(_1202)), float3(65504.0));
    half3 _1329 = normalize(half3(_793) + half3(_1174));
    half _1268 = clamp(dot(_777, half3(_1174)), half(0.0), half(1.0));
    half _1272 = clamp(dot(_777, _1329), half(0.0), half(1.0));
    half4 _1398 = half4(cross(_777, _1329), half(params.facet_alpha) * _1272) * half(64.0);
    half _1367 = _1268 + _953;
    half _1372 = half(4096.0) * half(params.facet_alpha);
    half _1375 = half(6.283185482025146484375) * max(mix((half(2.0) * _1268) * _953, _1367, half(params.facet_alpha)), half(0.000244140625));
    half _1377 = _1372 / (dot(_1398, _1398) * _1375);
    half _1431 = half(8192.0) * fma(half(-float(_1268)), _953, _1367);
    half _1435 = half(1.0) / (_1114 * _1431);
    half _1442 = half(2048.0) * _1114;
    float3 _1500 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1503 = dot(_1500, _1500);
    float3 _1508 = _1500 * rsqrt(fast::max(_1503, 9.9999999392252902907785028219223e-09));
    float _1512 = _1503 * float(frame.punctualLights[1].positionFalloff.w);
    float _1517 = fast::clamp(fma(-_1512, _1512, 1.0), 0.0, 1.0);
    float _1536 = fast::clamp(fma(dot(-_1508, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1547 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1517) * half(_1517)) / fast::max(_1503, 9.9999997473787516355514526367188e-05)) * half(_1536)) * half(_1536)), float3(65504.0));
    half3 _1663 = normalize(half3(_793) + half3(_1508));
    half _1602 = clamp(dot(_777, half3(_1508)), half(0.0), half(1.0));
    half _1606 = clamp(dot(_777, _1663), half(0.0), half(1.0));
    half4 _1732 = half4(cross(_777, _1663), half(params.facet_alpha) * _1606) * half(64.0);
    half _1701 = _1602 + _953;
    half _1709 = half(6.283185482025146484375) * max(mix((half(2.0) * _1602) * _953, _1701, half(params.facet_alpha)), half(0.000244140625));
    half _1711 = _1372 / (dot(_1732, _1732) * _1709);
    half _1765 = half(8192.0) * fma(half(-float(_1602)), _953, _1701);
    half _1769 = half(1.0) / (_1114 * _1765);
    half3 _1798 = (fma(half4(_1129).xyz, _1105 * _1068, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1021).xyz * (mix(half4(_992).xxx, half4(_992).yyy, half3(float3(params.facet_f0))) * _1011)) * _1070) + min(fma((half3(float3(params.facet_f0)) * min(_1377 * (_1377 * _1375), half(65504.0))) * _1011, (half3(_1213) * _1268) * _1070, (_1105 * ((((fma(_1435, _1431, half(2.0)) * pow(max(fma(half(-float(_1272)), _1272, half(1.0)), half(0.0)), half(0.5) * (_1435 * _1431))) * half(0.15915493667125701904296875)) * (_1268 * (_1435 * _1442))) * _1075)) * half3(_1213)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1711 * (_1711 * _1709), half(65504.0))) * _1011, (half3(_1547) * _1602) * _1070, (_1105 * ((((fma(_1769, _1765, half(2.0)) * pow(max(fma(half(-float(_1606)), _1606, half(1.0)), half(0.0)), half(0.5) * (_1769 * _1765))) * half(0.15915493667125701904296875)) * (_1602 * (_1769 * _1442))) * _1075)) * half3(_1547)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1798, half(1.0)));
    return out;
}

