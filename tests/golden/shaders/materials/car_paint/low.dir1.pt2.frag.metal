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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _817 = normalize(half3(in.v_normal));
    float3 _823 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1059 = max(dot(_817, half3(_823)), half(9.9999997473787516355514526367188e-05));
    half3 _1063 = reflect(-half3(_823), _817);
    float4 _1102 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1059, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1077 = facet_environment.sample(facet_environmentSmplr, float3(_1063), level(params.facet_environmentLod));
    half3 _1081 = mix(half4(_1102).xxx, half4(_1102).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1102).y) - half(1.0))));
    half _1167 = half(1.0) - _1059;
    half _1170 = _1167 * _1167;
    half _1177 = fma(half(0.959999978542327880859375), (_1170 * _1170) * _1167, half(0.039999999105930328369140625));
    half _1147 = fma(half(-float(_1177)), half(params.facet_clearCoat), half(1.0));
    float4 _1155 = facet_environment.sample(facet_environmentSmplr, float3(_1063), level(params.facet_clearCoatLod));
    half3 _865 = half4(frame.lightDirection).xyz;
    half3 _1301 = normalize(half3(_823) + _865);
    half _1245 = clamp(dot(_865, _1301), half(0.0), half(1.0));
    half _1326 = clamp(dot(_1063, _865), half(0.0), half(1.0));
    half _1329 = _1326 * _1326;
    half4 _2360 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1329 * _1329, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1341 = _2360.x;
    half3 _1424 = cross(_817, _1301) * half(64.0);
    half _1426 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1428 = _1426 * clamp(dot(_817, _1301), half(0.0), half(1.0));
    half _1380 = half(12.56637096405029296875) * max(_1245 * _1245, half(6.103515625e-05));
    half _1382 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1386 = _1382 / (fma(_1428, _1428, dot(_1424, _1424)) * _1380);
    half _1396 = half(1.0) - _1245;
    half _1399 = _1396 * _1396;
    half _1404 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1494 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1497 = dot(_1494, _1494);
    float3 _1502 = _1494 * rsqrt(fast::max(_1497, 9.9999999392252902907785028219223e-09));
    float _1506 = _1497 * float(frame.punctualLights[0].positionFalloff.w);
    float _1511 = fast::clamp(fma(-_1506, _1506, 1.0), 0.0, 1.0);
    float _1530 = fast::clamp(fma(dot(-_1502, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1662 = normalize(half3(_823) + half3(_1502));
    half _1606 = clamp(dot(half3(_1502), _1662), half(0.0), half(1.0));
    half _1687 = clamp(dot(_1063, half3(_1502)), half(0.0), half(1.0));
    half _1690 = _1687 * _1687;
    half4 _2406 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1690 * _1690, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1702 = _2406.x;
    half3 _1785 = cross(_817, _1662) * half(64.0);
    half _1789 = _1426 * clamp(dot(_817, _1662), half(0.0), half(1.0));
    half _1741 = half(12.56637096405029296875) * max(_1606 * _1606, half(6.103515625e-05));
    half _1747 = _1382 / (fma(_1789, _1789, dot(_1785, _1785)) * _1741);
    half _1757 = half(1.0) - _1606;
    half _1760 = _1757 * _1757;
    float3 _1855 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1858 = dot(_1855, _1855);
    float3 _1863 = _1855 * rsqrt(fast::max(_1858, 9.9999999392252902907785028219223e-09));
    float _1867 = _1858 * float(frame.punctualLights[1].positionFalloff.w);
    float _1872 = fast::clamp(fma(-_1867, _1867, 1.0), 0.0, 1.0);
    float _1891 = fast::clamp(fma(dot(-_1863, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _2023 = normalize(half3(_823) + half3(_1863));
    half _1967 = clamp(dot(half3(_1863), _2023), half(0.0), half(1.0));
    half _2048 = clamp(dot(_1063, half3(_1863)), half(0.0), half(1.0));
    half _2051 = _2048 * _2048;
    half4 _2447 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_2051 * _2051, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _2063 = _2447.x;
    half3 _2146 = cross(_817, _2023) * half(64.0);
    half _2150 = _1426 * clamp(dot(_817, _2023), half(0.0), half(1.0));
    half _2102 = half(12.56637096405029296875) * max(_1967 * _1967, half(6.103515625e-05));
    half _2108 = _1382 / (fma(_2150, _2150, dot(_2146, _2146)) * _2102);
    half _2118 = half(1.0) - _1967;
    half _2121 = _2118 * _2118;
    half3 _2180 = ((mix(half4(_1077).xyz * _1081, half4(_1155).xyz, half3(_1177 * half(params.facet_clearCoat))) + min(min(((_1081 * ((_1341 * _1341) * half(5.092957973480224609375))) * _1147) + half3(min(_1386 * (_1386 * _1380), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1404 * ((_1399 * _1399) * _1396))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_817, _865), half(0.0), half(1.0))), half3(float3(65504.0)))) + min(min(((_1081 * ((_1702 * _1702) * half(5.092957973480224609375))) * _1147) + half3(min(_1747 * (_1747 * _1741), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1404 * ((_1760 * _1760) * _1757))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1511) * half(_1511)) / fast::max(_1497, 9.9999997473787516355514526367188e-05)) * half(_1530)) * half(_1530)), float3(65504.0))) * clamp(dot(_817, half3(_1502)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min(min(((_1081 * ((_2063 * _2063) * half(5.092957973480224609375))) * _1147) + half3(min(_2108 * (_2108 * _2102), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1404 * ((_2121 * _2121) * _2118))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1872) * half(_1872)) / fast::max(_1858, 9.9999997473787516355514526367188e-05)) * half(_1891)) * half(_1891)), float3(65504.0))) * clamp(dot(_817, half3(_1863)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2180, half(1.0)));
    return out;
}

