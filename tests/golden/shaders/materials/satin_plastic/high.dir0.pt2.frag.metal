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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _968 = normalize(half3(in.v_normal));
    float3 _974 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1120 = _968.y;
    half _1125 = _968.z;
    half _1130 = _968.x;
    half3 _1198 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1120)) + (half4(frame.sh[2]).xyz * _1125)) + (half4(frame.sh[3]).xyz * _1130)) + (((((half4(frame.sh[4]).xyz * (_1130 * _1120)) + (half4(frame.sh[5]).xyz * (_1120 * _1125))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1125, _1125, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1130 * _1125))) + (half4(frame.sh[8]).xyz * fma(_1130, _1130, half(-float(_1120 * _1120))))), half3(float3(0.0)));
    half _1248 = max(dot(_968, half3(_974)), half(9.9999997473787516355514526367188e-05));
    half3 _1252 = reflect(-half3(_974), _968);
    float4 _1287 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1248, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1306 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1287).y) - half(1.0)));
    float4 _1318 = facet_environment.sample(facet_environmentSmplr, float3(_1252), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1395 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1352 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1248, _1395)), level(0.0));
    half3 _1402 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2411 = half4(_1352);
    half _1365 = _2411.z;
    half _1367 = fma(half(-float(max(_1402.x, max(_1402.y, _1402.z)))), _1365, half(1.0));
    half _1411 = _1395 * _1395;
    half4 _2415 = half4(_1352);
    half _1372 = _2415.w;
    float4 _1428 = facet_environment.sample(facet_environmentSmplr, float3(_1252), level(_1395 * (half(4.0) * (half(2.0) - _1395))));
    float3 _1465 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1468 = dot(_1465, _1465);
    float3 _1473 = _1465 * rsqrt(fast::max(_1468, 9.9999999392252902907785028219223e-09));
    float _1477 = _1468 * float(frame.punctualLights[0].positionFalloff.w);
    float _1482 = fast::clamp(fma(-_1477, _1477, 1.0), 0.0, 1.0);
    float _1501 = fast::clamp(fma(dot(-_1473, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1512 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1482) * half(_1482)) / fast::max(_1468, 9.9999997473787516355514526367188e-05)) * half(_1501)) * half(_1501)), float3(65504.0));
    float3 _1637 = fast::normalize(_974 + _1473);
    half _1569 = clamp(dot(_968, half3(_1473)), half(0.0), half(1.0));
    half _1573 = clamp(dot(_968, half3(_1637)), half(0.0), half(1.0));
    half3 _1677 = cross(_968, half3(_1637));
    half _1680 = _1573 * half(params.facet_alpha);
    half _1689 = half(params.facet_alpha) / fma(_1680, _1680, dot(_1677, _1677));
    half _1703 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1709 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1713 = sqrt(fma(_1248 * _1248, _1709, _1703));
    half _1737 = half(1.0) - clamp(dot(half3(_1473), half3(_1637)), half(0.0), half(1.0));
    half _1740 = _1737 * _1737;
    half3 _1748 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1781 = half(8192.0) * fma(half(-float(_1569)), _1248, _1569 + _1248);
    half _1785 = half(1.0) / (_1411 * _1781);
    half _1792 = half(2048.0) * _1411;
    half3 _1610 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1618 = min(fma(fma((half3(float3(params.facet_f0)) + (_1748 * ((_1740 * _1740) * _1737))) * min(min((_1689 * _1689) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1569, _1713, _1248 * sqrt(fma(_1569 * _1569, _1709, _1703))), half(65504.0)), half(65504.0)), _1306, _1610), (half3(_1512) * _1569) * _1367, (_1402 * ((((fma(_1785, _1781, half(2.0)) * pow(max(fma(half(-float(_1573)), _1573, half(1.0)), half(0.0)), half(0.5) * (_1785 * _1781))) * half(0.15915493667125701904296875)) * (_1569 * (_1785 * _1792))) * _1372)) * half3(_1512)), half3(float3(65504.0)));
    float3 _1856 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1859 = dot(_1856, _1856);
    float3 _1864 = _1856 * rsqrt(fast::max(_1859, 9.9999999392252902907785028219223e-09));
    float _1868 = _1859 * float(frame.punctualLights[1].positionFalloff.w);
    float _1873 = fast::clamp(fma(-_1868, _1868, 1.0), 0.0, 1.0);
    float _1892 = fast::clamp(fma(dot(-_1864, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1903 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1873) * half(_1873)) / fast::max(_1859, 9.9999997473787516355514526367188e-05)) * half(_1892)) * half(_1892)), float3(65504.0));
    float3 _2028 = fast::normalize(_974 + _1864);
    half _1960 = clamp(dot(_968, half3(_1864)), half(0.0), half(1.0));
    half _1964 = clamp(dot(_968, half3(_2028)), half(0.0), half(1.0));
    half3 _2068 = cross(_968, half3(_2028));
    half _2071 = _1964 * half(params.facet_alpha);
    half _2080 = half(params.facet_alpha) / fma(_2071, _2071, dot(_2068, _2068));
    half _2128 = half(1.0) - clamp(dot(half3(_1864), half3(_2028)), half(0.0), half(1.0));
    half _2131 = _2128 * _2128;
    half _2172 = half(8192.0) * fma(half(-float(_1960)), _1248, _1960 + _1248);
    half _2176 = half(1.0) / (_1411 * _2172);
    half3 _2009 = min(fma(fma((half3(float3(params.facet_f0)) + (_1748 * ((_2131 * _2131) * _2128))) * min(min((_2080 * _2080) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1960, _1713, _1248 * sqrt(fma(_1960 * _1960, _1709, _1703))), half(65504.0)), half(65504.0)), _1306, _1610), (half3(_1903) * _1960) * _1367, (_1402 * ((((fma(_2176, _2172, half(2.0)) * pow(max(fma(half(-float(_1964)), _1964, half(1.0)), half(0.0)), half(0.5) * (_2176 * _2172))) * half(0.15915493667125701904296875)) * (_1960 * (_2176 * _1792))) * _1372)) * half3(_1903)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1428).xyz, _1402 * _1365, fma(half3(float3(params.facet_diffuseColor)), _1198, half4(_1318).xyz * (mix(half4(_1287).xxx, half4(_1287).yyy, half3(float3(params.facet_f0))) * _1306)) * _1367) + _1618) + _2009, half(1.0)));
    return out;
}

