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
    float3 _962 = fast::normalize(in.v_normal);
    float3 _968 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1251 = fast::max(dot(_962, _968), 9.9999997473787516355514526367188e-05);
    float3 _1255 = reflect(-_968, _962);
    float4 _1290 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1251, params.facet_perceptualRoughness), level(0.0));
    float3 _1309 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1290.y) - 1.0));
    float _1367 = 1.0 - _1251;
    float _1370 = _1367 * _1367;
    float _1377 = fma(0.959999978542327880859375, (_1370 * _1370) * _1367, 0.039999999105930328369140625);
    float _1382 = fast::clamp(params.coat, 0.0, 1.0);
    float _1349 = fma(-_1377, _1382, 1.0);
    float _1387 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1433 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1436 = dot(_1433, _1433);
    float3 _1441 = _1433 * rsqrt(fast::max(_1436, 9.9999999392252902907785028219223e-09));
    float _1445 = _1436 * float(frame.punctualLights[0].positionFalloff.w);
    float _1450 = fast::clamp(fma(-_1445, _1445, 1.0), 0.0, 1.0);
    float _1469 = fast::clamp(fma(dot(-_1441, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1601 = fast::normalize(_968 + _1441);
    float _1535 = fast::clamp(dot(_962, _1441), 0.0, 1.0);
    float _1539 = fast::clamp(dot(_962, _1601), 0.0, 1.0);
    float _1543 = fast::clamp(dot(_1441, _1601), 0.0, 1.0);
    float _1639 = 4096.0 * params.facet_alpha;
    float3 _1655 = cross(_962, _1601);
    float _1659 = _1655.x;
    float4 _1663 = float4(_1659, _1655.yz, params.facet_alpha * _1539) * 64.0;
    float _1645 = _1639 / dot(_1663, _1663);
    float _1674 = params.facet_alpha * params.facet_alpha;
    float _1680 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1684 = sqrt(fma(_1251 * _1251, _1680, _1674));
    float _1707 = 1.0 - _1543;
    float _1710 = _1707 * _1707;
    float _1715 = (_1710 * _1710) * _1707;
    float3 _1718 = float3(1.0) - float3(params.facet_f0);
    float3 _1561 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1450 * _1450) / fast::max(_1436, 9.9999997473787516355514526367188e-05)) * _1469) * _1469)) * _1535;
    float _1754 = _1387 * _1387;
    float4 _1806 = float4(_1659, _1655.yz, _1754 * _1539) * 64.0;
    float _1764 = 12.56637096405029296875 * fast::max(_1543 * _1543, 6.103515625e-05);
    float _1766 = 4096.0 * _1754;
    float _1770 = _1766 / (dot(_1806, _1806) * _1764);
    float3 _1884 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1887 = dot(_1884, _1884);
    float3 _1892 = _1884 * rsqrt(fast::max(_1887, 9.9999999392252902907785028219223e-09));
    float _1896 = _1887 * float(frame.punctualLights[1].positionFalloff.w);
    float _1901 = fast::clamp(fma(-_1896, _1896, 1.0), 0.0, 1.0);
    float _1920 = fast::clamp(fma(dot(-_1892, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2052 = fast::normalize(_968 + _1892);
    float _1986 = fast::clamp(dot(_962, _1892), 0.0, 1.0);
    float _1990 = fast::clamp(dot(_962, _2052), 0.0, 1.0);
    float _1994 = fast::clamp(dot(_1892, _2052), 0.0, 1.0);
    float3 _2106 = cross(_962, _2052);
    float _2110 = _2106.x;
    float4 _2114 = float4(_2110, _2106.yz, params.facet_alpha * _1990) * 64.0;
    float _2096 = _1639 / dot(_2114, _2114);
    float _2158 = 1.0 - _1994;
    float _2161 = _2158 * _2158;
    float _2166 = (_2161 * _2161) * _2158;
    float3 _2012 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1901 * _1901) / fast::max(_1887, 9.9999997473787516355514526367188e-05)) * _1920) * _1920)) * _1986;
    float4 _2257 = float4(_2110, _2106.yz, _1754 * _1990) * 64.0;
    float _2215 = 12.56637096405029296875 * fast::max(_1994 * _1994, 6.103515625e-05);
    float _2221 = _1766 / (dot(_2257, _2257) * _2215);
    float3 _2300 = (mix(facet_environment.sample(facet_environmentSmplr, _1255, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1290.xxx, _1290.yyy, float3(params.facet_f0)) * _1309), facet_environment.sample(facet_environmentSmplr, _1255, level(_1387 * (4.0 * (2.0 - _1387)))).xyz, float3(_1377 * _1382)) + fast::min(fma(((float3(params.facet_f0) + (_1718 * _1715)) * (((_1645 * _1645) * 0.3183098733425140380859375) * (0.5 / fma(_1535, _1684, _1251 * sqrt(fma(_1535 * _1535, _1680, _1674)))))) * _1309, _1561 * _1349, _1561 * ((_1770 * (_1770 * _1764)) * (fma(0.959999978542327880859375, _1715, 0.039999999105930328369140625) * _1382))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1718 * _2166)) * (((_2096 * _2096) * 0.3183098733425140380859375) * (0.5 / fma(_1986, _1684, _1251 * sqrt(fma(_1986 * _1986, _1680, _1674)))))) * _1309, _2012 * _1349, _2012 * ((_2221 * (_2221 * _2215)) * (fma(0.959999978542327880859375, _2166, 0.039999999105930328369140625) * _1382))), float3(65504.0));
    out.fragColor = float4(_2300, 1.0);
    return out;
}

