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
    float3 _933 = fast::normalize(in.v_normal);
    float3 _939 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1225 = fast::max(dot(_933, _939), 9.9999997473787516355514526367188e-05);
    float3 _1229 = reflect(-_939, _933);
    float4 _1264 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1225, params.facet_perceptualRoughness), level(0.0));
    float3 _1283 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1264.y) - 1.0));
    float _1336 = 1.0 - _1225;
    float _1339 = _1336 * _1336;
    float _1351 = fast::clamp(params.coat, 0.0, 1.0);
    float _1356 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1399 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1402 = dot(_1399, _1399);
    float3 _1407 = _1399 * rsqrt(fast::max(_1402, 9.9999999392252902907785028219223e-09));
    float _1411 = _1402 * float(frame.punctualLights[0].positionFalloff.w);
    float _1416 = fast::clamp(fma(-_1411, _1411, 1.0), 0.0, 1.0);
    float _1435 = fast::clamp(fma(dot(-_1407, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1571 = fast::normalize(_939 + _1407);
    float _1503 = fast::clamp(dot(_933, _1407), 0.0, 1.0);
    float _1507 = fast::clamp(dot(_933, _1571), 0.0, 1.0);
    float _1511 = fast::clamp(dot(_1407, _1571), 0.0, 1.0);
    float3 _1609 = cross(_933, _1571);
    float _1612 = _1507 * params.facet_alpha;
    float _1616 = dot(_1609, _1609);
    float _1621 = params.facet_alpha / fma(_1612, _1612, _1616);
    float _1634 = params.facet_alpha * params.facet_alpha;
    float _1640 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1644 = sqrt(fma(_1225 * _1225, _1640, _1634));
    float _1667 = 1.0 - _1511;
    float _1670 = _1667 * _1667;
    float _1675 = (_1670 * _1670) * _1667;
    float3 _1678 = float3(1.0) - float3(params.facet_f0);
    float3 _1529 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1416 * _1416) / fast::max(_1402, 9.9999997473787516355514526367188e-05)) * _1435) * _1435)) * _1503;
    float _1750 = fma(0.959999978542327880859375, _1675, 0.039999999105930328369140625);
    float _1715 = _1356 * _1356;
    float _1767 = _1507 * _1715;
    float _1776 = _1715 / fma(_1767, _1767, _1616);
    float3 _1842 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1845 = dot(_1842, _1842);
    float3 _1850 = _1842 * rsqrt(fast::max(_1845, 9.9999999392252902907785028219223e-09));
    float _1854 = _1845 * float(frame.punctualLights[1].positionFalloff.w);
    float _1859 = fast::clamp(fma(-_1854, _1854, 1.0), 0.0, 1.0);
    float _1878 = fast::clamp(fma(dot(-_1850, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2014 = fast::normalize(_939 + _1850);
    float _1946 = fast::clamp(dot(_933, _1850), 0.0, 1.0);
    float _1950 = fast::clamp(dot(_933, _2014), 0.0, 1.0);
    float _1954 = fast::clamp(dot(_1850, _2014), 0.0, 1.0);
    float3 _2052 = cross(_933, _2014);
    float _2055 = _1950 * params.facet_alpha;
    float _2059 = dot(_2052, _2052);
    float _2064 = params.facet_alpha / fma(_2055, _2055, _2059);
    float _2110 = 1.0 - _1954;
    float _2113 = _2110 * _2110;
    float _2118 = (_2113 * _2113) * _2110;
    float3 _1972 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1859 * _1859) / fast::max(_1845, 9.9999997473787516355514526367188e-05)) * _1878) * _1878)) * _1946;
    float _2193 = fma(0.959999978542327880859375, _2118, 0.039999999105930328369140625);
    float _2210 = _1950 * _1715;
    float _2219 = _1715 / fma(_2210, _2210, _2059);
    float3 _2250 = (mix(facet_environment.sample(facet_environmentSmplr, _1229, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1264.xxx, _1264.yyy, float3(params.facet_f0)) * _1283), facet_environment.sample(facet_environmentSmplr, _1229, level(_1356 * 4.0)).xyz, float3(fma(0.959999978542327880859375, (_1339 * _1339) * _1336, 0.039999999105930328369140625) * _1351)) + fast::min(fma(((float3(params.facet_f0) + (_1678 * _1675)) * (((_1621 * _1621) * 0.3183098733425140380859375) * (0.5 / fma(_1503, _1644, _1225 * sqrt(fma(_1503 * _1503, _1640, _1634)))))) * _1283, _1529 * fma(-_1750, _1351, 1.0), _1529 * ((((_1776 * _1776) * 0.3183098733425140380859375) * (0.25 / fast::max(_1511 * _1511, 6.103515625e-05))) * (_1750 * _1351))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1678 * _2118)) * (((_2064 * _2064) * 0.3183098733425140380859375) * (0.5 / fma(_1946, _1644, _1225 * sqrt(fma(_1946 * _1946, _1640, _1634)))))) * _1283, _1972 * fma(-_2193, _1351, 1.0), _1972 * ((((_2219 * _2219) * 0.3183098733425140380859375) * (0.25 / fast::max(_1954 * _1954, 6.103515625e-05))) * (_2193 * _1351))), float3(65504.0));
    out.fragColor = float4(_2250, 1.0);
    return out;
}

