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
    half3 _761 = normalize(half3(in.v_normal));
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _958 = max(dot(_761, half3(_777)), half(9.9999997473787516355514526367188e-05));
    half3 _962 = reflect(-half3(_777), _761);
    float4 _997 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_958, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1016 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_997).y) - half(1.0)));
    float4 _1028 = facet_environment.sample(facet_environmentSmplr, float3(_962), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1105 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1062 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_958, _1105)), level(0.0));
    half3 _1112 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2185 = half4(_1062);
    half _1075 = _2185.z;
    half _1077 = fma(half(-float(max(_1112.x, max(_1112.y, _1112.z)))), _1075, half(1.0));
    half _1121 = _1105 * _1105;
    half4 _2189 = half4(_1062);
    half _1082 = _2189.w;
    float4 _1138 = facet_environment.sample(facet_environmentSmplr, float3(_962), level(_1105 * (half(4.0) * (half(2.0) - _1105))));
    half3 _823 = half4(frame.lightDirection).xyz;
    half3 _835 = half4(frame.lightColor).xyz;
    half3 _1254 = normalize(half3(_777) + _823);
    half _1193 = clamp(dot(_761, _823), half(0.0), half(1.0));
    half _1197 = clamp(dot(_761, _1254), half(0.0), half(1.0));
    half3 _1281 = cross(_761, _1254);
    half _1284 = _1197 * half(params.facet_alpha);
    half _1298 = _1193 + _958;
    half _1301 = max(mix((half(2.0) * _1193) * _958, _1298, half(params.facet_alpha)), half(0.000244140625));
    half _1303 = half(1024.0) * half(params.facet_alpha);
    half _1308 = _1303 / (fma(_1284, _1284, dot(_1281, _1281)) * (half(6433.98193359375) * _1301));
    half _1345 = half(8192.0) * fma(half(-float(_1193)), _958, _1298);
    half _1349 = half(1.0) / (_1121 * _1345);
    half _1356 = half(2048.0) * _1121;
    float3 _1414 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1417 = dot(_1414, _1414);
    float3 _1422 = _1414 * rsqrt(fast::max(_1417, 9.9999999392252902907785028219223e-09));
    float _1426 = _1417 * float(frame.punctualLights[0].positionFalloff.w);
    float _1431 = fast::clamp(fma(-_1426, _1426, 1.0), 0.0, 1.0);
    float _1450 = fast::clamp(fma(dot(-_1422, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1461 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1431) * half(_1431)) / fast::max(_1417, 9.9999997473787516355514526367188e-05)) * half(_1450)) * half(_1450)), float3(65504.0));
    half3 _1577 = normalize(half3(_777) + half3(_1422));
    half _1516 = clamp(dot(_761, half3(_1422)), half(0.0), half(1.0));
    half _1520 = clamp(dot(_761, _1577), half(0.0), half(1.0));
    half3 _1604 = cross(_761, _1577);
    half _1607 = _1520 * half(params.facet_alpha);
    half _1621 = _1516 + _958;
    half _1624 = max(mix((half(2.0) * _1516) * _958, _1621, half(params.facet_alpha)), half(0.000244140625));
    half _1631 = _1303 / (fma(_1607, _1607, dot(_1604, _1604)) * (half(6433.98193359375) * _1624));
    half _1668 = half(8192.0) * fma(half(-float(_1516)), _958, _1621);
    half _1672 = half(1.0) / (_1121 * _1668);
    half3 _1701 = (fma(half4(_1138).xyz, _1112 * _1075, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1028).xyz * (mix(half4(_997).xxx, half4(_997).yyy, half3(float3(params.facet_f0))) * _1016)) * _1077) + min(fma((half3(float3(params.facet_f0)) * min(_1308 * (_1308 * (half(6.283185482025146484375) * _1301)), half(65504.0))) * _1016, (_835 * _1193) * _1077, (_1112 * ((((fma(_1349, _1345, half(2.0)) * pow(max(fma(half(-float(_1197)), _1197, half(1.0)), half(0.0)), half(0.5) * (_1349 * _1345))) * half(0.15915493667125701904296875)) * (_1193 * (_1349 * _1356))) * _1082)) * _835), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1631 * (_1631 * (half(6.283185482025146484375) * _1624)), half(65504.0))) * _1016, (half3(_1461) * _1516) * _1077, (_1112 * ((((fma(_1672, _1668, half(2.0)) * pow(max(fma(half(-float(_1520)), _1520, half(1.0)), half(0.0)), half(0.5) * (_1672 * _1668))) * half(0.15915493667125701904296875)) * (_1516 * (_1672 * _1356))) * _1082)) * half3(_1461)), half3(float3(65504.0)));
    float3 _1737 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1740 = dot(_1737, _1737);
    float3 _1745 = _1737 * rsqrt(fast::max(_1740, 9.9999999392252902907785028219223e-09));
    float _1749 = _1740 * float(frame.punctualLights[1].positionFalloff.w);
    float _1754 = fast::clamp(fma(-_1749, _1749, 1.0), 0.0, 1.0);
    float _1773 = fast::clamp(fma(dot(-_1745, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1784 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1754) * half(_1754)) / fast::max(_1740, 9.9999997473787516355514526367188e-05)) * half(_1773)) * half(_1773)), float3(65504.0));
    half3 _1900 = normalize(half3(_777) + half3(_1745));
    half _1839 = clamp(dot(_761, half3(_1745)), half(0.0), half(1.0));
    half _1843 = clamp(dot(_761, _1900), half(0.0), half(1.0));
    half3 _1927 = cross(_761, _1900);
    half _1930 = _1843 * half(params.facet_alpha);
    half _1944 = _1839 + _958;
    half _1947 = max(mix((half(2.0) * _1839) * _958, _1944, half(params.facet_alpha)), half(0.000244140625));
    half _1954 = _1303 / (fma(_1930, _1930, dot(_1927, _1927)) * (half(6433.98193359375) * _1947));
    half _1991 = half(8192.0) * fma(half(-float(_1839)), _958, _1944);
    half _1995 = half(1.0) / (_1121 * _1991);
    out.fragColor = float4(half4(_1701 + min(fma((half3(float3(params.facet_f0)) * min(_1954 * (_1954 * (half(6.283185482025146484375) * _1947)), half(65504.0))) * _1016, (half3(_1784) * _1839) * _1077, (_1112 * ((((fma(_1995, _1991, half(2.0)) * pow(max(fma(half(-float(_1843)), _1843, half(1.0)), half(0.0)), half(0.5) * (_1995 * _1991))) * half(0.15915493667125701904296875)) * (_1839 * (_1995 * _1356))) * _1082)) * half3(_1784)), half3(float3(65504.0))), half(1.0)));
    return out;
}

