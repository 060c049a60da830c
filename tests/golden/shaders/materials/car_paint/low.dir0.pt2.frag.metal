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
    half _1038 = max(dot(_817, half3(_823)), half(9.9999997473787516355514526367188e-05));
    half3 _1042 = reflect(-half3(_823), _817);
    float4 _1081 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1038, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1056 = facet_environment.sample(facet_environmentSmplr, float3(_1042), level(params.facet_environmentLod));
    half3 _1060 = mix(half4(_1081).xxx, half4(_1081).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1081).y) - half(1.0))));
    half _1146 = half(1.0) - _1038;
    half _1149 = _1146 * _1146;
    half _1156 = fma(half(0.959999978542327880859375), (_1149 * _1149) * _1146, half(0.039999999105930328369140625));
    half _1126 = fma(half(-float(_1156)), half(params.facet_clearCoat), half(1.0));
    float4 _1134 = facet_environment.sample(facet_environmentSmplr, float3(_1042), level(params.facet_clearCoatLod));
    float3 _1196 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1199 = dot(_1196, _1196);
    float3 _1204 = _1196 * rsqrt(fast::max(_1199, 9.9999999392252902907785028219223e-09));
    float _1208 = _1199 * float(frame.punctualLights[0].positionFalloff.w);
    float _1213 = fast::clamp(fma(-_1208, _1208, 1.0), 0.0, 1.0);
    float _1232 = fast::clamp(fma(dot(-_1204, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1364 = normalize(half3(_823) + half3(_1204));
    half _1308 = clamp(dot(half3(_1204), _1364), half(0.0), half(1.0));
    half _1389 = clamp(dot(_1042, half3(_1204)), half(0.0), half(1.0));
    half _1392 = _1389 * _1389;
    half4 _2071 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1392 * _1392, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1404 = _2071.x;
    half3 _1487 = cross(_817, _1364) * half(64.0);
    half _1489 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1491 = _1489 * clamp(dot(_817, _1364), half(0.0), half(1.0));
    half _1443 = half(12.56637096405029296875) * max(_1308 * _1308, half(6.103515625e-05));
    half _1445 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1449 = _1445 / (fma(_1491, _1491, dot(_1487, _1487)) * _1443);
    half _1459 = half(1.0) - _1308;
    half _1462 = _1459 * _1459;
    half _1467 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1557 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1560 = dot(_1557, _1557);
    float3 _1565 = _1557 * rsqrt(fast::max(_1560, 9.9999999392252902907785028219223e-09));
    float _1569 = _1560 * float(frame.punctualLights[1].positionFalloff.w);
    float _1574 = fast::clamp(fma(-_1569, _1569, 1.0), 0.0, 1.0);
    float _1593 = fast::clamp(fma(dot(-_1565, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1725 = normalize(half3(_823) + half3(_1565));
    half _1669 = clamp(dot(half3(_1565), _1725), half(0.0), half(1.0));
    half _1750 = clamp(dot(_1042, half3(_1565)), half(0.0), half(1.0));
    half _1753 = _1750 * _1750;
    half4 _2118 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1753 * _1753, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1765 = _2118.x;
    half3 _1848 = cross(_817, _1725) * half(64.0);
    half _1852 = _1489 * clamp(dot(_817, _1725), half(0.0), half(1.0));
    half _1804 = half(12.56637096405029296875) * max(_1669 * _1669, half(6.103515625e-05));
    half _1810 = _1445 / (fma(_1852, _1852, dot(_1848, _1848)) * _1804);
    half _1820 = half(1.0) - _1669;
    half _1823 = _1820 * _1820;
    half3 _1882 = (mix(half4(_1056).xyz * _1060, half4(_1134).xyz, half3(_1156 * half(params.facet_clearCoat))) + min(min(((_1060 * ((_1404 * _1404) * half(5.092957973480224609375))) * _1126) + half3(min(_1449 * (_1449 * _1443), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1467 * ((_1462 * _1462) * _1459))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1213) * half(_1213)) / fast::max(_1199, 9.9999997473787516355514526367188e-05)) * half(_1232)) * half(_1232)), float3(65504.0))) * clamp(dot(_817, half3(_1204)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min(min(((_1060 * ((_1765 * _1765) * half(5.092957973480224609375))) * _1126) + half3(min(_1810 * (_1810 * _1804), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1467 * ((_1823 * _1823) * _1820))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1574) * half(_1574)) / fast::max(_1560, 9.9999997473787516355514526367188e-05)) * half(_1593)) * half(_1593)), float3(65504.0))) * clamp(dot(_817, half3(_1565)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1882, half(1.0)));
    return out;
}

