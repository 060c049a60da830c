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
    half3 _1010 = normalize(half3(in.v_normal));
    float3 _1016 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1162 = _1010.y;
    half _1167 = _1010.z;
    half _1172 = _1010.x;
    half3 _1240 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1162)) + (half4(frame.sh[2]).xyz * _1167)) + (half4(frame.sh[3]).xyz * _1172)) + (((((half4(frame.sh[4]).xyz * (_1172 * _1162)) + (half4(frame.sh[5]).xyz * (_1162 * _1167))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1167, _1167, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1172 * _1167))) + (half4(frame.sh[8]).xyz * fma(_1172, _1172, half(-float(_1162 * _1162))))), half3(float3(0.0)));
    half _1290 = max(dot(_1010, half3(_1016)), half(9.9999997473787516355514526367188e-05));
    half3 _1294 = reflect(-half3(_1016), _1010);
    float4 _1329 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1290, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1348 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1329).y) - half(1.0)));
    float4 _1355 = facet_environment.sample(facet_environmentSmplr, float3(_1294), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1428 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1388 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1290, _1428)), level(0.0));
    half3 _1435 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2589 = half4(_1388);
    half _1401 = _2589.z;
    half _1403 = fma(half(-float(max(_1435.x, max(_1435.y, _1435.z)))), _1401, half(1.0));
    half4 _2593 = half4(_1388);
    half _1405 = _2593.w;
    float4 _1442 = facet_environment.sample(facet_environmentSmplr, float3(_1294), level(_1428 * half(4.0)));
    float3 _1479 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1482 = dot(_1479, _1479);
    float3 _1487 = _1479 * rsqrt(fast::max(_1482, 9.9999999392252902907785028219223e-09));
    float _1491 = _1482 * float(frame.punctualLights[0].positionFalloff.w);
    float _1496 = fast::clamp(fma(-_1491, _1491, 1.0), 0.0, 1.0);
    float _1515 = fast::clamp(fma(dot(-_1487, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1526 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1496) * half(_1496)) / fast::max(_1482, 9.9999997473787516355514526367188e-05)) * half(_1515)) * half(_1515)), float3(65504.0));
    float3 _1666 = fast::normalize(_1016 + _1487);
    half _1607 = clamp(dot(_1010, half3(_1487)), half(0.0), half(1.0));
    half _1611 = clamp(dot(_1010, half3(_1666)), half(0.0), half(1.0));
    half3 _1706 = cross(_1010, half3(_1666));
    half _1709 = _1611 * half(params.facet_alpha);
    half _1718 = half(params.facet_alpha) / fma(_1709, _1709, dot(_1706, _1706));
    half _1732 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1738 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1742 = sqrt(fma(_1290 * _1290, _1738, _1732));
    half _1766 = half(1.0) - clamp(dot(half3(_1487), half3(_1666)), half(0.0), half(1.0));
    half _1769 = _1766 * _1766;
    half3 _1777 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1641 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half _1849 = _1428 * _1428;
    half _1869 = half(8192.0) * fma(half(-float(_1607)), _1290, _1607 + _1290);
    half _1873 = half(1.0) / (_1849 * _1869);
    half _1880 = half(2048.0) * _1849;
    half3 _1914 = fma(half4(_1442).xyz, _1435 * _1401, fma(half3(float3(params.facet_diffuseColor)), _1240, half4(_1355).xyz * (mix(half4(_1329).xxx, half4(_1329).yyy, half3(float3(params.facet_f0))) * _1348)) * _1403) + (min(fma((half3(float3(params.facet_f0)) + (_1777 * ((_1769 * _1769) * _1766))) * min(min((_1718 * _1718) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1607, _1742, _1290 * sqrt(fma(_1607 * _1607, _1738, _1732))), half(65504.0)), half(65504.0)), _1348, _1641) * ((half3(_1526) * _1607) * _1403), half3(float3(65504.0))) + min((_1435 * ((((fma(_1873, _1869, half(2.0)) * pow(max(fma(half(-float(_1611)), _1611, half(1.0)), half(0.0)), half(0.5) * (_1873 * _1869))) * half(0.15915493667125701904296875)) * (_1607 * (_1873 * _1880))) * _1405)) * half3(_1526), half3(float3(65504.0))));
    float3 _1950 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1953 = dot(_1950, _1950);
    float3 _1958 = _1950 * rsqrt(fast::max(_1953, 9.9999999392252902907785028219223e-09));
    float _1962 = _1953 * float(frame.punctualLights[1].positionFalloff.w);
    float _1967 = fast::clamp(fma(-_1962, _1962, 1.0), 0.0, 1.0);
    float _1986 = fast::clamp(fma(dot(-_1958, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1997 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1967) * half(_1967)) / fast::max(_1953, 9.9999997473787516355514526367188e-05)) * half(_1986)) * half(_1986)), float3(65504.0));
    float3 _2137 = fast::normalize(_1016 + _1958);
    half _2078 = clamp(dot(_1010, half3(_1958)), half(0.0), half(1.0));
    half _2082 = clamp(dot(_1010, half3(_2137)), half(0.0), half(1.0));
    half3 _2177 = cross(_1010, half3(_2137));
    half _2180 = _2082 * half(params.facet_alpha);
    half _2189 = half(params.facet_alpha) / fma(_2180, _2180, dot(_2177, _2177));
    half _2237 = half(1.0) - clamp(dot(half3(_1958), half3(_2137)), half(0.0), half(1.0));
    half _2240 = _2237 * _2237;
    half _2340 = half(8192.0) * fma(half(-float(_2078)), _1290, _2078 + _1290);
    half _2344 = half(1.0) / (_1849 * _2340);
    half3 _2385 = _1914 + (min(fma((half3(float3(params.facet_f0)) + (_1777 * ((_2240 * _2240) * _2237))) * min(min((_2189 * _2189) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2078, _1742, _1290 * sqrt(fma(_2078 * _2078, _1738, _1732))), half(65504.0)), half(65504.0)), _1348, _1641) * ((half3(_1997) * _2078) * _1403), half3(float3(65504.0))) + min((_1435 * ((((fma(_2344, _2340, half(2.0)) * pow(max(fma(half(-float(_2082)), _2082, half(1.0)), half(0.0)), half(0.5) * (_2344 * _2340))) * half(0.15915493667125701904296875)) * (_2078 * (_2344 * _1880))) * _1405)) * half3(_1997), half3(float3(65504.0))));
    out.fragColor = float4(half4(_2385, half(1.0)));
    return out;
}

