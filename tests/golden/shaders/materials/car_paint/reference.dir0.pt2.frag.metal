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
    float3 _958 = fast::normalize(in.v_normal);
    float3 _964 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1247 = fast::max(dot(_958, _964), 9.9999997473787516355514526367188e-05);
    float3 _1251 = reflect(-_964, _958);
    float4 _1286 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1247, params.facet_perceptualRoughness), level(0.0));
    float3 _1305 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1286.y) - 1.0));
    float _1360 = 1.0 - _1247;
    float _1363 = _1360 * _1360;
    float _1370 = fma(0.959999978542327880859375, (_1363 * _1363) * _1360, 0.039999999105930328369140625);
    float _1375 = fast::clamp(params.coat, 0.0, 1.0);
    float _1342 = fma(-_1370, _1375, 1.0);
    float _1380 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1423 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1426 = dot(_1423, _1423);
    float3 _1431 = _1423 * rsqrt(fast::max(_1426, 9.9999999392252902907785028219223e-09));
    float _1435 = _1426 * float(frame.punctualLights[0].positionFalloff.w);
    float _1440 = fast::clamp(fma(-_1435, _1435, 1.0), 0.0, 1.0);
    float _1459 = fast::clamp(fma(dot(-_1431, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1591 = fast::normalize(_964 + _1431);
    float _1525 = fast::clamp(dot(_958, _1431), 0.0, 1.0);
    float _1529 = fast::clamp(dot(_958, _1591), 0.0, 1.0);
    float _1533 = fast::clamp(dot(_1431, _1591), 0.0, 1.0);
    float _1629 = 4096.0 * params.facet_alpha;
    float3 _1645 = cross(_958, _1591);
    float _1649 = _1645.x;
    float4 _1653 = float4(_1649, _1645.yz, params.facet_alpha * _1529) * 64.0;
    float _1635 = _1629 / dot(_1653, _1653);
    float _1664 = params.facet_alpha * params.facet_alpha;
    float _1670 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1674 = sqrt(fma(_1247 * _1247, _1670, _1664));
    float _1697 = 1.0 - _1533;
    float _1700 = _1697 * _1697;
    float _1705 = (_1700 * _1700) * _1697;
    float3 _1708 = float3(1.0) - float3(params.facet_f0);
    float3 _1551 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1440 * _1440) / fast::max(_1426, 9.9999997473787516355514526367188e-05)) * _1459) * _1459)) * _1525;
    float _1744 = _1380 * _1380;
    float4 _1796 = float4(_1649, _1645.yz, _1744 * _1529) * 64.0;
    float _1754 = 12.56637096405029296875 * fast::max(_1533 * _1533, 6.103515625e-05);
    float _1756 = 4096.0 * _1744;
    float _1760 = _1756 / (dot(_1796, _1796) * _1754);
    float3 _1874 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1877 = dot(_1874, _1874);
    float3 _1882 = _1874 * rsqrt(fast::max(_1877, 9.9999999392252902907785028219223e-09));
    float _1886 = _1877 * float(frame.punctualLights[1].positionFalloff.w);
    float _1891 = fast::clamp(fma(-_1886, _1886, 1.0), 0.0, 1.0);
    float _1910 = fast::clamp(fma(dot(-_1882, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2042 = fast::normalize(_964 + _1882);
    float _1976 = fast::clamp(dot(_958, _1882), 0.0, 1.0);
    float _1980 = fast::clamp(dot(_958, _2042), 0.0, 1.0);
    float _1984 = fast::clamp(dot(_1882, _2042), 0.0, 1.0);
    float3 _2096 = cross(_958, _2042);
    float _2100 = _2096.x;
    float4 _2104 = float4(_2100, _2096.yz, params.facet_alpha * _1980) * 64.0;
    float _2086 = _1629 / dot(_2104, _2104);
    float _2148 = 1.0 - _1984;
    float _2151 = _2148 * _2148;
    float _2156 = (_2151 * _2151) * _2148;
    float3 _2002 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1891 * _1891) / fast::max(_1877, 9.9999997473787516355514526367188e-05)) * _1910) * _1910)) * _1976;
    float4 _2247 = float4(_2100, _2096.yz, _1744 * _1980) * 64.0;
    float _2205 = 12.56637096405029296875 * fast::max(_1984 * _1984, 6.103515625e-05);
    float _2211 = _1756 / (dot(_2247, _2247) * _2205);
    float3 _2290 = (mix(facet_environment.sample(facet_environmentSmplr, _1251, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1286.xxx, _1286.yyy, float3(params.facet_f0)) * _1305), facet_environment.sample(facet_environmentSmplr, _1251, level(_1380 * 4.0)).xyz, float3(_1370 * _1375)) + fast::min(fma(((float3(params.facet_f0) + (_1708 * _1705)) * (((_1635 * _1635) * 0.3183098733425140380859375) * (0.5 / fma(_1525, _1674, _1247 * sqrt(fma(_1525 * _1525, _1670, _1664)))))) * _1305, _1551 * _1342, _1551 * ((_1760 * (_1760 * _1754)) * (fma(0.959999978542327880859375, _1705, 0.039999999105930328369140625) * _1375))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1708 * _2156)) * (((_2086 * _2086) * 0.3183098733425140380859375) * (0.5 / fma(_1976, _1674, _1247 * sqrt(fma(_1976 * _1976, _1670, _1664)))))) * _1305, _2002 * _1342, _2002 * ((_2211 * (_2211 * _2205)) * (fma(0.959999978542327880859375, _2156, 0.039999999105930328369140625) * _1375))), float3(65504.0));
    out.fragColor = float4(_2290, 1.0);
    return out;
}

