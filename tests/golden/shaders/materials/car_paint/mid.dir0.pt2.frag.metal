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
    half _1046 = max(dot(_827, half3(_833)), half(9.9999997473787516355514526367188e-05));
    half3 _1050 = reflect(-half3(_833), _827);
    float4 _1088 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1046, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1107 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1088).y) - half(1.0)));
    float4 _1064 = facet_environment.sample(facet_environmentSmplr, float3(_1050), level(params.facet_environmentLod));
    half _1153 = half(1.0) - _1046;
    half _1156 = _1153 * _1153;
    half _1163 = fma(half(0.959999978542327880859375), (_1156 * _1156) * _1153, half(0.039999999105930328369140625));
    half _1133 = fma(half(-float(_1163)), half(params.facet_clearCoat), half(1.0));
    float4 _1141 = facet_environment.sample(facet_environmentSmplr, float3(_1050), level(params.facet_clearCoatLod));
    float3 _1203 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1206 = dot(_1203, _1203);
    float3 _1211 = _1203 * rsqrt(fast::max(_1206, 9.9999999392252902907785028219223e-09));
    float _1215 = _1206 * float(frame.punctualLights[0].positionFalloff.w);
    float _1220 = fast::clamp(fma(-_1215, _1215, 1.0), 0.0, 1.0);
    float _1239 = fast::clamp(fma(dot(-_1211, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1304 = clamp(dot(_827, half3(_1211)), half(0.0), half(1.0));
    half3 _1374 = normalize(half3(_833) + half3(_1211));
    half _1311 = clamp(dot(_827, _1374), half(0.0), half(1.0));
    half _1315 = clamp(dot(half3(_1211), _1374), half(0.0), half(1.0));
    half3 _1437 = cross(_827, _1374) * half(64.0);
    half _1439 = half(64.0) * half(params.facet_alpha);
    half _1441 = _1439 * _1311;
    half _1444 = dot(_1437, _1437);
    half _1417 = half(4096.0) * half(params.facet_alpha);
    half _1420 = half(6.283185482025146484375) * max(mix((half(2.0) * _1304) * _1046, _1304 + _1046, half(params.facet_alpha)), half(0.000244140625));
    half _1422 = _1417 / (fma(_1441, _1441, _1444) * _1420);
    half _1529 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1531 = _1529 * _1311;
    half _1483 = half(12.56637096405029296875) * max(_1315 * _1315, half(6.103515625e-05));
    half _1485 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1489 = _1485 / (fma(_1531, _1531, _1444) * _1483);
    half _1499 = half(1.0) - _1315;
    half _1502 = _1499 * _1499;
    half _1507 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1597 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1600 = dot(_1597, _1597);
    float3 _1605 = _1597 * rsqrt(fast::max(_1600, 9.9999999392252902907785028219223e-09));
    float _1609 = _1600 * float(frame.punctualLights[1].positionFalloff.w);
    float _1614 = fast::clamp(fma(-_1609, _1609, 1.0), 0.0, 1.0);
    float _1633 = fast::clamp(fma(dot(-_1605, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1698 = clamp(dot(_827, half3(_1605)), half(0.0), half(1.0));
    half3 _1768 = normalize(half3(_833) + half3(_1605));
    half _1705 = clamp(dot(_827, _1768), half(0.0), half(1.0));
    half _1709 = clamp(dot(half3(_1605), _1768), half(0.0), half(1.0));
    half3 _1831 = cross(_827, _1768) * half(64.0);
    half _1835 = _1439 * _1705;
    half _1838 = dot(_1831, _1831);
    half _1814 = half(6.283185482025146484375) * max(mix((half(2.0) * _1698) * _1046, _1698 + _1046, half(params.facet_alpha)), half(0.000244140625));
    half _1816 = _1417 / (fma(_1835, _1835, _1838) * _1814);
    half _1925 = _1529 * _1705;
    half _1877 = half(12.56637096405029296875) * max(_1709 * _1709, half(6.103515625e-05));
    half _1883 = _1485 / (fma(_1925, _1925, _1838) * _1877);
    half _1893 = half(1.0) - _1709;
    half _1896 = _1893 * _1893;
    half3 _1955 = (mix(half4(_1064).xyz * (mix(half4(_1088).xxx, half4(_1088).yyy, half3(float3(params.facet_f0))) * _1107), half4(_1141).xyz, half3(_1163 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1422 * (_1422 * _1420), half(65504.0))) * _1107) * _1133) + half3(min(_1489 * (_1489 * _1483), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1507 * ((_1502 * _1502) * _1499))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1220) * half(_1220)) / fast::max(_1206, 9.9999997473787516355514526367188e-05)) * half(_1239)) * half(_1239)), float3(65504.0))) * _1304), half3(float3(65504.0)))) + min(min((((half3(float3(params.facet_f0)) * min(_1816 * (_1816 * _1814), half(65504.0))) * _1107) * _1133) + half3(min(_1883 * (_1883 * _1877), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1507 * ((_1896 * _1896) * _1893))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1614) * half(_1614)) / fast::max(_1600, 9.9999997473787516355514526367188e-05)) * half(_1633)) * half(_1633)), float3(65504.0))) * _1698), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1955, half(1.0)));
    return out;
}

