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
    half3 _786 = normalize(half3(in.v_normal));
    float3 _802 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _986 = max(dot(_786, half3(_802)), half(9.9999997473787516355514526367188e-05));
    half3 _990 = reflect(-half3(_802), _786);
    float4 _1026 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_986, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1052 = facet_environment.sample(facet_environmentSmplr, float3(_990), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1005 = mix(half4(_1026).xxx, half4(_1026).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1026).y) - half(1.0))));
    half _1125 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1085 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_986, _1125)), level(0.0));
    half3 _1132 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2368 = half4(_1085);
    half _1098 = _2368.z;
    half _1100 = fma(half(-float(max(_1132.x, max(_1132.y, _1132.z)))), _1098, half(1.0));
    half4 _2372 = half4(_1085);
    half _1102 = _2372.w;
    float4 _1139 = facet_environment.sample(facet_environmentSmplr, float3(_990), level(_1125 * half(4.0)));
    half3 _848 = half4(frame.lightDirection).xyz;
    half3 _860 = half4(frame.lightColor).xyz;
    half _1218 = clamp(dot(_786, _848), half(0.0), half(1.0));
    half _1292 = clamp(dot(_990, _848), half(0.0), half(1.0));
    half _1295 = _1292 * _1292;
    half4 _2387 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1295 * _1295, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1307 = _2387.x;
    half _1345 = clamp(dot(_786, normalize(half3(_802) + _848)), half(0.0), half(1.0));
    half _1372 = _1125 * _1125;
    half _1392 = half(8192.0) * fma(half(-float(_1218)), _986, _1218 + _986);
    half _1396 = half(1.0) / (_1372 * _1392);
    half _1403 = half(2048.0) * _1372;
    float3 _1473 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1476 = dot(_1473, _1473);
    float3 _1481 = _1473 * rsqrt(fast::max(_1476, 9.9999999392252902907785028219223e-09));
    float _1485 = _1476 * float(frame.punctualLights[0].positionFalloff.w);
    float _1490 = fast::clamp(fma(-_1485, _1485, 1.0), 0.0, 1.0);
    float _1509 = fast::clamp(fma(dot(-_1481, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1520 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1490) * half(_1490)) / fast::max(_1476, 9.9999997473787516355514526367188e-05)) * half(_1509)) * half(_1509)), float3(65504.0));
    half _1599 = clamp(dot(_786, half3(_1481)), half(0.0), half(1.0));
    half _1673 = clamp(dot(_990, half3(_1481)), half(0.0), half(1.0));
    half _1676 = _1673 * _1673;
    half4 _2428 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1676 * _1676, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1688 = _2428.x;
    half _1726 = clamp(dot(_786, normalize(half3(_802) + half3(_1481))), half(0.0), half(1.0));
    half _1773 = half(8192.0) * fma(half(-float(_1599)), _986, _1599 + _986);
    half _1777 = half(1.0) / (_1372 * _1773);
    half3 _1818 = (fma(half4(_1139).xyz, _1132 * _1098, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1052).xyz * _1005) * _1100) + (min((_1005 * ((_1307 * _1307) * half(5.092957973480224609375))) * ((_860 * _1218) * _1100), half3(float3(65504.0))) + min((_1132 * ((((fma(_1396, _1392, half(2.0)) * pow(max(fma(half(-float(_1345)), _1345, half(1.0)), half(0.0)), half(0.5) * (_1396 * _1392))) * half(0.15915493667125701904296875)) * (_1218 * (_1396 * _1403))) * _1102)) * _860, half3(float3(65504.0))))) + (min((_1005 * ((_1688 * _1688) * half(5.092957973480224609375))) * ((half3(_1520) * _1599) * _1100), half3(float3(65504.0))) + min((_1132 * ((((fma(_1777, _1773, half(2.0)) * pow(max(fma(half(-float(_1726)), _1726, half(1.0)), half(0.0)), half(0.5) * (_1777 * _1773))) * half(0.15915493667125701904296875)) * (_1599 * (_1777 * _1403))) * _1102)) * half3(_1520), half3(float3(65504.0))));
    float3 _1854 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1857 = dot(_1854, _1854);
    float3 _1862 = _1854 * rsqrt(fast::max(_1857, 9.9999999392252902907785028219223e-09));
    float _1866 = _1857 * float(frame.punctualLights[1].positionFalloff.w);
    float _1871 = fast::clamp(fma(-_1866, _1866, 1.0), 0.0, 1.0);
    float _1890 = fast::clamp(fma(dot(-_1862, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1901 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1871) * half(_1871)) / fast::max(_1857, 9.9999997473787516355514526367188e-05)) * half(_1890)) * half(_1890)), float3(65504.0));
    half _1980 = clamp(dot(_786, half3(_1862)), half(0.0), half(1.0));
    half _2054 = clamp(dot(_990, half3(_1862)), half(0.0), half(1.0));
    half _2057 = _2054 * _2054;
    half4 _2471 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_2057 * _2057, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _2069 = _2471.x;
    half _2107 = clamp(dot(_786, normalize(half3(_802) + half3(_1862))), half(0.0), half(1.0));
    half _2154 = half(8192.0) * fma(half(-float(_1980)), _986, _1980 + _986);
    half _2158 = half(1.0) / (_1372 * _2154);
    out.fragColor = float4(half4(_1818 + (min((_1005 * ((_2069 * _2069) * half(5.092957973480224609375))) * ((half3(_1901) * _1980) * _1100), half3(float3(65504.0))) + min((_1132 * ((((fma(_2158, _2154, half(2.0)) * pow(max(fma(half(-float(_2107)), _2107, half(1.0)), half(0.0)), half(0.5) * (_2158 * _2154))) * half(0.15915493667125701904296875)) * (_1980 * (_2158 * _1403))) * _1102)) * half3(_1901), half3(float3(65504.0)))), half(1.0)));
    return out;
}

