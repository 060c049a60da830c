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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _832 = normalize(half3(in.v_normal));
    float3 _838 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1076 = max(dot(_832, half3(_838)), half(9.9999997473787516355514526367188e-05));
    half3 _1080 = reflect(-half3(_838), _832);
    float4 _1116 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1076, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1145 = facet_environment.sample(facet_environmentSmplr, float3(_1080), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1095 = mix(half4(_1116).xxx, half4(_1116).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1116).y) - half(1.0))));
    half _1192 = half(1.0) - _1076;
    half _1195 = _1192 * _1192;
    half _1202 = fma(half(0.959999978542327880859375), (_1195 * _1195) * _1192, half(0.039999999105930328369140625));
    half _1172 = fma(half(-float(_1202)), half(params.facet_clearCoat), half(1.0));
    float4 _1180 = facet_environment.sample(facet_environmentSmplr, float3(_1080), level(params.facet_clearCoatLod));
    half3 _880 = half4(frame.lightDirection).xyz;
    half3 _1326 = normalize(half3(_838) + _880);
    half _1270 = clamp(dot(_880, _1326), half(0.0), half(1.0));
    half _1351 = clamp(dot(_1080, _880), half(0.0), half(1.0));
    half _1354 = _1351 * _1351;
    half4 _2389 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1354 * _1354, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1366 = _2389.x;
    half3 _1449 = cross(_832, _1326) * half(64.0);
    half _1451 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1453 = _1451 * clamp(dot(_832, _1326), half(0.0), half(1.0));
    half _1405 = half(12.56637096405029296875) * max(_1270 * _1270, half(6.103515625e-05));
    half _1407 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1411 = _1407 / (fma(_1453, _1453, dot(_1449, _1449)) * _1405);
    half _1421 = half(1.0) - _1270;
    half _1424 = _1421 * _1421;
    half _1429 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1519 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1522 = dot(_1519, _1519);
    float3 _1527 = _1519 * rsqrt(fast::max(_1522, 9.9999999392252902907785028219223e-09));
    float _1531 = _1522 * float(frame.punctualLights[0].positionFalloff.w);
    float _1536 = fast::clamp(fma(-_1531, _1531, 1.0), 0.0, 1.0);
    float _1555 = fast::clamp(fma(dot(-_1527, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1687 = normalize(half3(_838) + half3(_1527));
    half _1631 = clamp(dot(half3(_1527), _1687), half(0.0), half(1.0));
    half _1712 = clamp(dot(_1080, half3(_1527)), half(0.0), half(1.0));
    half _1715 = _1712 * _1712;
    half4 _2435 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1715 * _1715, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1727 = _2435.x;
    half3 _1810 = cross(_832, _1687) * half(64.0);
    half _1814 = _1451 * clamp(dot(_832, _1687), half(0.0), half(1.0));
    half _1766 = half(12.56637096405029296875) * max(_1631 * _1631, half(6.103515625e-05));
    half _1772 = _1407 / (fma(_1814, _1814, dot(_1810, _1810)) * _1766);
    half _1782 = half(1.0) - _1631;
    half _1785 = _1782 * _1782;
    float3 _1880 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1883 = dot(_1880, _1880);
    float3 _1888 = _1880 * rsqrt(fast::max(_1883, 9.9999999392252902907785028219223e-09));
    float _1892 = _1883 * float(frame.punctualLights[1].positionFalloff.w);
    float _1897 = fast::clamp(fma(-_1892, _1892, 1.0), 0.0, 1.0);
    float _1916 = fast::clamp(fma(dot(-_1888, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _2048 = normalize(half3(_838) + half3(_1888));
    half _1992 = clamp(dot(half3(_1888), _2048), half(0.0), half(1.0));
    half _2073 = clamp(dot(_1080, half3(_1888)), half(0.0), half(1.0));
    half _2076 = _2073 * _2073;
    half4 _2476 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_2076 * _2076, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _2088 = _2476.x;
    half3 _2171 = cross(_832, _2048) * half(64.0);
    half _2175 = _1451 * clamp(dot(_832, _2048), half(0.0), half(1.0));
    half _2127 = half(12.56637096405029296875) * max(_1992 * _1992, half(6.103515625e-05));
    half _2133 = _1407 / (fma(_2175, _2175, dot(_2171, _2171)) * _2127);
    half _2143 = half(1.0) - _1992;
    half _2146 = _2143 * _2143;
    half3 _2205 = ((mix(half4(_1145).xyz * _1095, half4(_1180).xyz, half3(_1202 * half(params.facet_clearCoat))) + min(min(((_1095 * ((_1366 * _1366) * half(5.092957973480224609375))) * _1172) + half3(min(_1411 * (_1411 * _1405), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1429 * ((_1424 * _1424) * _1421))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_832, _880), half(0.0), half(1.0))), half3(float3(65504.0)))) + min(min(((_1095 * ((_1727 * _1727) * half(5.092957973480224609375))) * _1172) + half3(min(_1772 * (_1772 * _1766), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1429 * ((_1785 * _1785) * _1782))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1536) * half(_1536)) / fast::max(_1522, 9.9999997473787516355514526367188e-05)) * half(_1555)) * half(_1555)), float3(65504.0))) * clamp(dot(_832, half3(_1527)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min(min(((_1095 * ((_2088 * _2088) * half(5.092957973480224609375))) * _1172) + half3(min(_2133 * (_2133 * _2127), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1429 * ((_2146 * _2146) * _2143))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1897) * half(_1897)) / fast::max(_1883, 9.9999997473787516355514526367188e-05)) * half(_1916)) * half(_1916)), float3(65504.0))) * clamp(dot(_832, half3(_1888)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2205, half(1.0)));
    return out;
}

