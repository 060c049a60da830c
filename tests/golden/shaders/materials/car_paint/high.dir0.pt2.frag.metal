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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _969 = normalize(half3(in.v_normal));
    float3 _975 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1259 = max(dot(_969, half3(_975)), half(9.9999997473787516355514526367188e-05));
    half3 _1263 = reflect(-half3(_975), _969);
    float4 _1298 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1259, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1317 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1298).y) - half(1.0)));
    float4 _1327 = facet_environment.sample(facet_environmentSmplr, float3(_1263), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1374 = half(1.0) - _1259;
    half _1377 = _1374 * _1374;
    half _1384 = fma(half(0.959999978542327880859375), (_1377 * _1377) * _1374, half(0.039999999105930328369140625));
    half _1354 = fma(half(-float(_1384)), half(params.facet_clearCoat), half(1.0));
    float4 _1362 = facet_environment.sample(facet_environmentSmplr, float3(_1263), level(params.facet_clearCoatLod));
    float3 _1424 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1427 = dot(_1424, _1424);
    float3 _1432 = _1424 * rsqrt(fast::max(_1427, 9.9999999392252902907785028219223e-09));
    float _1436 = _1427 * float(frame.punctualLights[0].positionFalloff.w);
    float _1441 = fast::clamp(fma(-_1436, _1436, 1.0), 0.0, 1.0);
    float _1460 = fast::clamp(fma(dot(-_1432, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1596 = fast::normalize(_975 + _1432);
    half _1528 = clamp(dot(_969, half3(_1432)), half(0.0), half(1.0));
    half _1532 = clamp(dot(_969, half3(_1596)), half(0.0), half(1.0));
    half _1536 = clamp(dot(half3(_1432), half3(_1596)), half(0.0), half(1.0));
    half _1636 = half(4096.0) * half(params.facet_alpha);
    half3 _1655 = cross(_969, half3(_1596)) * half(64.0);
    half _1657 = half(64.0) * half(params.facet_alpha);
    half _1659 = _1657 * _1532;
    half _1662 = dot(_1655, _1655);
    half _1642 = _1636 / fma(_1659, _1659, _1662);
    half _1674 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1680 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1684 = sqrt(fma(_1259 * _1259, _1680, _1674));
    half _1708 = half(1.0) - _1536;
    half _1711 = _1708 * _1708;
    half _1716 = (_1711 * _1711) * _1708;
    half3 _1719 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1803 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1805 = _1803 * _1532;
    half _1757 = half(12.56637096405029296875) * max(_1536 * _1536, half(6.103515625e-05));
    half _1759 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1763 = _1759 / (fma(_1805, _1805, _1662) * _1757);
    half _1781 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    half3 _1577 = min(min(((((half3(float3(params.facet_f0)) + (_1719 * _1716)) * min(min((_1642 * _1642) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1528, _1684, _1259 * sqrt(fma(_1528 * _1528, _1680, _1674))), half(65504.0)), half(65504.0))) * _1317) * _1354) + half3(min(_1763 * (_1763 * _1757), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1781 * _1716)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1441) * half(_1441)) / fast::max(_1427, 9.9999997473787516355514526367188e-05)) * half(_1460)) * half(_1460)), float3(65504.0))) * _1528), half3(float3(65504.0)));
    float3 _1871 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1874 = dot(_1871, _1871);
    float3 _1879 = _1871 * rsqrt(fast::max(_1874, 9.9999999392252902907785028219223e-09));
    float _1883 = _1874 * float(frame.punctualLights[1].positionFalloff.w);
    float _1888 = fast::clamp(fma(-_1883, _1883, 1.0), 0.0, 1.0);
    float _1907 = fast::clamp(fma(dot(-_1879, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2043 = fast::normalize(_975 + _1879);
    half _1975 = clamp(dot(_969, half3(_1879)), half(0.0), half(1.0));
    half _1979 = clamp(dot(_969, half3(_2043)), half(0.0), half(1.0));
    half _1983 = clamp(dot(half3(_1879), half3(_2043)), half(0.0), half(1.0));
    half3 _2102 = cross(_969, half3(_2043)) * half(64.0);
    half _2106 = _1657 * _1979;
    half _2109 = dot(_2102, _2102);
    half _2089 = _1636 / fma(_2106, _2106, _2109);
    half _2155 = half(1.0) - _1983;
    half _2158 = _2155 * _2155;
    half _2163 = (_2158 * _2158) * _2155;
    half _2252 = _1803 * _1979;
    half _2204 = half(12.56637096405029296875) * max(_1983 * _1983, half(6.103515625e-05));
    half _2210 = _1759 / (fma(_2252, _2252, _2109) * _2204);
    half3 _2024 = min(min(((((half3(float3(params.facet_f0)) + (_1719 * _2163)) * min(min((_2089 * _2089) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1975, _1684, _1259 * sqrt(fma(_1975 * _1975, _1680, _1674))), half(65504.0)), half(65504.0))) * _1317) * _1354) + half3(min(_2210 * (_2210 * _2204), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1781 * _2163)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1888) * half(_1888)) / fast::max(_1874, 9.9999997473787516355514526367188e-05)) * half(_1907)) * half(_1907)), float3(65504.0))) * _1975), half3(float3(65504.0)));
    out.fragColor = float4(half4((mix(half4(_1327).xyz * (mix(half4(_1298).xxx, half4(_1298).yyy, half3(float3(params.facet_f0))) * _1317), half4(_1362).xyz, half3(_1384 * half(params.facet_clearCoat))) + _1577) + _2024, half(1.0)));
    return out;
}

