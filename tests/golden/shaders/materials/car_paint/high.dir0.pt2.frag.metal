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
    half3 _962 = normalize(half3(in.v_normal));
    float3 _968 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1251 = max(dot(_962, half3(_968)), half(9.9999997473787516355514526367188e-05));
    half3 _1255 = reflect(-half3(_968), _962);
    float4 _1290 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1251, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1309 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1290).y) - half(1.0)));
    float4 _1319 = facet_environment.sample(facet_environmentSmplr, float3(_1255), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1367 = half(1.0) - _1251;
    half _1370 = _1367 * _1367;
    half _1377 = fma(half(0.959999978542327880859375), (_1370 * _1370) * _1367, half(0.039999999105930328369140625));
    half _1382 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1349 = fma(half(-float(_1377)), _1382, half(1.0));
    half _1387 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1397 = facet_environment.sample(facet_environmentSmplr, float3(_1255), level(_1387 * (half(4.0) * (half(2.0) - _1387))));
    float3 _1434 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1437 = dot(_1434, _1434);
    float3 _1442 = _1434 * rsqrt(fast::max(_1437, 9.9999999392252902907785028219223e-09));
    float _1446 = _1437 * float(frame.punctualLights[0].positionFalloff.w);
    float _1451 = fast::clamp(fma(-_1446, _1446, 1.0), 0.0, 1.0);
    float _1470 = fast::clamp(fma(dot(-_1442, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1606 = fast::normalize(_968 + _1442);
    half _1539 = clamp(dot(_962, half3(_1442)), half(0.0), half(1.0));
    half _1543 = clamp(dot(_962, half3(_1606)), half(0.0), half(1.0));
    half _1547 = clamp(dot(half3(_1442), half3(_1606)), half(0.0), half(1.0));
    half3 _1646 = cross(_962, half3(_1606));
    half _1649 = _1543 * half(params.facet_alpha);
    half _1653 = dot(_1646, _1646);
    half _1658 = half(params.facet_alpha) / fma(_1649, _1649, _1653);
    half _1672 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1678 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1682 = sqrt(fma(_1251 * _1251, _1678, _1672));
    half _1706 = half(1.0) - _1547;
    half _1709 = _1706 * _1706;
    half _1714 = (_1709 * _1709) * _1706;
    half3 _1717 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1565 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1451) * half(_1451)) / fast::max(_1437, 9.9999997473787516355514526367188e-05)) * half(_1470)) * half(_1470)), float3(65504.0))) * _1539;
    half _1751 = _1387 * _1387;
    half _1757 = _1543 * _1751;
    half _1768 = max(_1547 * _1547, half(6.103515625e-05));
    half _1771 = half(2048.0) * _1751;
    half _1776 = _1771 / (fma(_1757, _1757, _1653) * (_1768 * half(25735.927734375)));
    float3 _1875 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1878 = dot(_1875, _1875);
    float3 _1883 = _1875 * rsqrt(fast::max(_1878, 9.9999999392252902907785028219223e-09));
    float _1887 = _1878 * float(frame.punctualLights[1].positionFalloff.w);
    float _1892 = fast::clamp(fma(-_1887, _1887, 1.0), 0.0, 1.0);
    float _1911 = fast::clamp(fma(dot(-_1883, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2047 = fast::normalize(_968 + _1883);
    half _1980 = clamp(dot(_962, half3(_1883)), half(0.0), half(1.0));
    half _1984 = clamp(dot(_962, half3(_2047)), half(0.0), half(1.0));
    half _1988 = clamp(dot(half3(_1883), half3(_2047)), half(0.0), half(1.0));
    half3 _2087 = cross(_962, half3(_2047));
    half _2090 = _1984 * half(params.facet_alpha);
    half _2094 = dot(_2087, _2087);
    half _2099 = half(params.facet_alpha) / fma(_2090, _2090, _2094);
    half _2147 = half(1.0) - _1988;
    half _2150 = _2147 * _2147;
    half _2155 = (_2150 * _2150) * _2147;
    half3 _2006 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1892) * half(_1892)) / fast::max(_1878, 9.9999997473787516355514526367188e-05)) * half(_1911)) * half(_1911)), float3(65504.0))) * _1980;
    half _2198 = _1984 * _1751;
    half _2209 = max(_1988 * _1988, half(6.103515625e-05));
    half _2217 = _1771 / (fma(_2198, _2198, _2094) * (_2209 * half(25735.927734375)));
    half3 _2280 = (mix(half4(_1319).xyz * (mix(half4(_1290).xxx, half4(_1290).yyy, half3(float3(params.facet_f0))) * _1309), half4(_1397).xyz, half3(_1377 * _1382)) + min(fma(((half3(float3(params.facet_f0)) + (_1717 * _1714)) * min(min((_1658 * _1658) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1539, _1682, _1251 * sqrt(fma(_1539 * _1539, _1678, _1672))), half(65504.0)), half(65504.0))) * _1309, _1565 * _1349, _1565 * (min(_1776 * (_1776 * (half(12.56637096405029296875) * _1768)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1714, half(0.039999999105930328369140625)) * _1382))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1717 * _2155)) * min(min((_2099 * _2099) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1980, _1682, _1251 * sqrt(fma(_1980 * _1980, _1678, _1672))), half(65504.0)), half(65504.0))) * _1309, _2006 * _1349, _2006 * (min(_2217 * (_2217 * (half(12.56637096405029296875) * _2209)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2155, half(0.039999999105930328369140625)) * _1382))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2280, half(1.0)));
    return out;
}

