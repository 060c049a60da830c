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
    half3 _744 = normalize(half3(in.v_normal));
    float3 _760 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _944 = max(dot(_744, half3(_760)), half(9.9999997473787516355514526367188e-05));
    half3 _948 = reflect(-half3(_760), _744);
    float4 _984 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_944, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1015 = facet_environment.sample(facet_environmentSmplr, float3(_948), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _963 = mix(half4(_984).xxx, half4(_984).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_984).y) - half(1.0))));
    half _1092 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1049 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_944, _1092)), level(0.0));
    half3 _1099 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2112 = half4(_1049);
    half _1062 = _2112.z;
    half _1064 = fma(half(-float(max(_1099.x, max(_1099.y, _1099.z)))), _1062, half(1.0));
    half _1108 = _1092 * _1092;
    half4 _2116 = half4(_1049);
    half _1069 = _2116.w;
    float4 _1125 = facet_environment.sample(facet_environmentSmplr, float3(_948), level(_1092 * (half(4.0) * (half(2.0) - _1092))));
    half3 _806 = half4(frame.lightDirection).xyz;
    half3 _818 = half4(frame.lightColor).xyz;
    half _1180 = clamp(dot(_744, _806), half(0.0), half(1.0));
    half _1184 = clamp(dot(_744, normalize(half3(_760) + _806)), half(0.0), half(1.0));
    half _1263 = clamp(dot(_948, _806), half(0.0), half(1.0));
    half _1266 = _1263 * _1263;
    half4 _2135 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1266 * _1266, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1278 = _2135.x;
    half _1312 = half(8192.0) * fma(half(-float(_1180)), _944, _1180 + _944);
    half _1316 = half(1.0) / (_1108 * _1312);
    half _1323 = half(2048.0) * _1108;
    float3 _1381 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1384 = dot(_1381, _1381);
    float3 _1389 = _1381 * rsqrt(fast::max(_1384, 9.9999999392252902907785028219223e-09));
    float _1393 = _1384 * float(frame.punctualLights[0].positionFalloff.w);
    float _1398 = fast::clamp(fma(-_1393, _1393, 1.0), 0.0, 1.0);
    float _1417 = fast::clamp(fma(dot(-_1389, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1428 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1398) * half(_1398)) / fast::max(_1384, 9.9999997473787516355514526367188e-05)) * half(_1417)) * half(_1417)), float3(65504.0));
    half _1483 = clamp(dot(_744, half3(_1389)), half(0.0), half(1.0));
    half _1487 = clamp(dot(_744, normalize(half3(_760) + half3(_1389))), half(0.0), half(1.0));
    half _1566 = clamp(dot(_948, half3(_1389)), half(0.0), half(1.0));
    half _1569 = _1566 * _1566;
    half4 _2176 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1569 * _1569, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1581 = _2176.x;
    half _1615 = half(8192.0) * fma(half(-float(_1483)), _944, _1483 + _944);
    half _1619 = half(1.0) / (_1108 * _1615);
    float3 _1684 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1687 = dot(_1684, _1684);
    float3 _1692 = _1684 * rsqrt(fast::max(_1687, 9.9999999392252902907785028219223e-09));
    float _1696 = _1687 * float(frame.punctualLights[1].positionFalloff.w);
    float _1701 = fast::clamp(fma(-_1696, _1696, 1.0), 0.0, 1.0);
    float _1720 = fast::clamp(fma(dot(-_1692, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1731 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1701) * half(_1701)) / fast::max(_1687, 9.9999997473787516355514526367188e-05)) * half(_1720)) * half(_1720)), float3(65504.0));
    half _1786 = clamp(dot(_744, half3(_1692)), half(0.0), half(1.0));
    half _1790 = clamp(dot(_744, normalize(half3(_760) + half3(_1692))), half(0.0), half(1.0));
    half _1869 = clamp(dot(_948, half3(_1692)), half(0.0), half(1.0));
    half _1872 = _1869 * _1869;
    half4 _2218 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1872 * _1872, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1884 = _2218.x;
    half _1918 = half(8192.0) * fma(half(-float(_1786)), _944, _1786 + _944);
    half _1922 = half(1.0) / (_1108 * _1918);
    half3 _1951 = ((fma(half4(_1125).xyz, _1099 * _1062, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1015).xyz * _963) * _1064) + min(fma(_963 * ((_1278 * _1278) * half(5.092957973480224609375)), (_818 * _1180) * _1064, (_1099 * ((((fma(_1316, _1312, half(2.0)) * pow(max(fma(half(-float(_1184)), _1184, half(1.0)), half(0.0)), half(0.5) * (_1316 * _1312))) * half(0.15915493667125701904296875)) * (_1180 * (_1316 * _1323))) * _1069)) * _818), half3(float3(65504.0)))) + min(fma(_963 * ((_1581 * _1581) * half(5.092957973480224609375)), (half3(_1428) * _1483) * _1064, (_1099 * ((((fma(_1619, _1615, half(2.0)) * pow(max(fma(half(-float(_1487)), _1487, half(1.0)), half(0.0)), half(0.5) * (_1619 * _1615))) * half(0.15915493667125701904296875)) * (_1483 * (_1619 * _1323))) * _1069)) * half3(_1428)), half3(float3(65504.0)))) + min(fma(_963 * ((_1884 * _1884) * half(5.092957973480224609375)), (half3(_1731) * _1786) * _1064, (_1099 * ((((fma(_1922, _1918, half(2.0)) * pow(max(fma(half(-float(_1790)), _1790, half(1.0)), half(0.0)), half(0.5) * (_1922 * _1918))) * half(0.15915493667125701904296875)) * (_1786 * (_1922 * _1323))) * _1069)) * half3(_1731)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1951, half(1.0)));
    return out;
}

