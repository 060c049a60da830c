#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _827 = normalize(half3(in.v_normal));
    float3 _833 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1067 = max(dot(_827, half3(_833)), half(9.9999997473787516355514526367188e-05));
    half3 _1071 = reflect(-half3(_833), _827);
    float4 _1109 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1067, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1128 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1109).y) - half(1.0)));
    float4 _1085 = facet_environment.sample(facet_environmentSmplr, float3(_1071), level(params.facet_environmentLod));
    half _1174 = half(1.0) - _1067;
    half _1177 = _1174 * _1174;
    half _1184 = fma(half(0.959999978542327880859375), (_1177 * _1177) * _1174, half(0.039999999105930328369140625));
    half _1154 = fma(half(-float(_1184)), half(params.facet_clearCoat), half(1.0));
    float4 _1162 = facet_environment.sample(facet_environmentSmplr, float3(_1071), level(params.facet_clearCoatLod));
    half3 _875 = half4(frame.lightDirection).xyz;
    half _1241 = clamp(dot(_827, _875), half(0.0), half(1.0));
    half3 _1311 = normalize(half3(_833) + _875);
    half _1248 = clamp(dot(_827, _1311), half(0.0), half(1.0));
    half _1252 = clamp(dot(_875, _1311), half(0.0), half(1.0));
    half3 _1374 = cross(_827, _1311) * half(64.0);
    half _1376 = half(64.0) * half(params.facet_alpha);
    half _1378 = _1376 * _1248;
    half _1381 = dot(_1374, _1374);
    half _1354 = half(4096.0) * half(params.facet_alpha);
    half _1357 = half(6.283185482025146484375) * max(mix((half(2.0) * _1241) * _1067, _1241 + _1067, half(params.facet_alpha)), half(0.000244140625));
    half _1359 = _1354 / (fma(_1378, _1378, _1381) * _1357);
    half _1466 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1468 = _1466 * _1248;
    half _1420 = half(12.56637096405029296875) * max(_1252 * _1252, half(6.103515625e-05));
    half _1422 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1426 = _1422 / (fma(_1468, _1468, _1381) * _1420);
    half _1436 = half(1.0) - _1252;
    half _1439 = _1436 * _1436;
    half _1444 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1534 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1537 = dot(_1534, _1534);
    float3 _1542 = _1534 * rsqrt(fast::max(_1537, 9.9999999392252902907785028219223e-09));
    float _1546 = _1537 * float(frame.punctualLights[0].positionFalloff.w);
    float _1551 = fast::clamp(fma(-_1546, _1546, 1.0), 0.0, 1.0);
    float _1570 = fast::clamp(fma(dot(-_1542, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1635 = clamp(dot(_827, half3(_1542)), half(0.0), half(1.0));
    half3 _1705 = normalize(half3(_833) + half3(_1542));
    half _1642 = clamp(dot(_827, _1705), half(0.0), half(1.0));
    half _1646 = clamp(dot(half3(_1542), _1705), half(0.0), half(1.0));
    half3 _1768 = cross(_827, _1705) * half(64.0);
    half _1772 = _1376 * _1642;
    half _1775 = dot(_1768, _1768);
    half _1751 = half(6.283185482025146484375) * max(mix((half(2.0) * _1635) * _1067, _1635 + _1067, half(params.facet_alpha)), half(0.000244140625));
    half _1753 = _1354 / (fma(_1772, _1772, _1775) * _1751);
    half _1862 = _1466 * _1642;
    half _1814 = half(12.56637096405029296875) * max(_1646 * _1646, half(6.103515625e-05));
    half _1820 = _1422 / (fma(_1862, _1862, _1775) * _1814);
    half _1830 = half(1.0) - _1646;
    half _1833 = _1830 * _1830;
    half3 _1892 = (mix(half4(_1085).xyz * (mix(half4(_1109).xxx, half4(_1109).yyy, half3(float3(params.facet_f0))) * _1128), half4(_1162).xyz, half3(_1184 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1359 * (_1359 * _1357), half(65504.0))) * _1128) * _1154) + half3(min(_1426 * (_1426 * _1420), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1444 * ((_1439 * _1439) * _1436))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1241), half3(float3(65504.0)))) + min(min((((half3(float3(params.facet_f0)) * min(_1753 * (_1753 * _1751), half(65504.0))) * _1128) * _1154) + half3(min(_1820 * (_1820 * _1814), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1444 * ((_1833 * _1833) * _1830))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1551) * half(_1551)) / fast::max(_1537, 9.9999997473787516355514526367188e-05)) * half(_1570)) * half(_1570)), float3(65504.0))) * _1635), half3(float3(65504.0)));
    float3 _1928 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1931 = dot(_1928, _1928);
    float3 _1936 = _1928 * rsqrt(fast::max(_1931, 9.9999999392252902907785028219223e-09));
    float _1940 = _1931 * float(frame.punctualLights[1].positionFalloff.w);
    float _1945 = fast::clamp(fma(-_1940, _1940, 1.0), 0.0, 1.0);
    float _1964 = fast::clamp(fma(dot(-_1936, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _2029 = clamp(dot(_827, half3(_1936)), half(0.0), half(1.0));
    half3 _2099 = normalize(half3(_833) + half3(_1936));
    half _2036 = clamp(dot(_827, _2099), half(0.0), half(1.0));
    half _2040 = clamp(dot(half3(_1936), _2099), half(0.0), half(1.0));
    half3 _2162 = cross(_827, _2099) * half(64.0);
    half _2166 = _1376 * _2036;
    half _2169 = dot(_2162, _2162);
    half _2145 = half(6.283185482025146484375) * max(mix((half(2.0) * _2029) * _1067, _2029 + _1067, half(params.facet_alpha)), half(0.000244140625));
    half _2147 = _1354 / (fma(_2166, _2166, _2169) * _2145);
    half _2256 = _1466 * _2036;
    half _2208 = half(12.56637096405029296875) * max(_2040 * _2040, half(6.103515625e-05));
    half _2214 = _1422 / (fma(_2256, _2256, _2169) * _2208);
    half _2224 = half(1.0) - _2040;
    half _2227 = _2224 * _2224;
    half3 _2286 = _1892 + min(min((((half3(float3(params.facet_f0)) * min(_2147 * (_2147 * _2145), half(65504.0))) * _1128) * _1154) + half3(min(_2214 * (_2214 * _2208), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1444 * ((_2227 * _2227) * _2224))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1945) * half(_1945)) / fast::max(_1931, 9.9999997473787516355514526367188e-05)) * half(_1964)) * half(_1964)), float3(65504.0))) * _2029), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2286, half(1.0)));
    return out;
}

