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
    float3 _1001 = fast::normalize(in.v_normal);
    float3 _1007 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1174 = _1001.y;
    float _1179 = _1001.z;
    float _1184 = _1001.x;
    float _1302 = fast::max(dot(_1001, _1007), 9.9999997473787516355514526367188e-05);
    float3 _1306 = reflect(-_1007, _1001);
    float4 _1341 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1302, params.facet_perceptualRoughness), level(0.0));
    float3 _1360 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1341.y) - 1.0));
    float _1440 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1400 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1302, _1440), level(0.0));
    float3 _1447 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1413 = _1400.z;
    float _1415 = fma(-fast::max(_1447.x, fast::max(_1447.y, _1447.z)), _1413, 1.0);
    float _1417 = _1400.w;
    float3 _1433 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1174)) + (frame.sh[2].xyz * _1179)) + (frame.sh[3].xyz * _1184)) + (((((frame.sh[4].xyz * (_1184 * _1174)) + (frame.sh[5].xyz * (_1174 * _1179))) + (frame.sh[6].xyz * fma(3.0 * _1179, _1179, -1.0))) + (frame.sh[7].xyz * (_1184 * _1179))) + (frame.sh[8].xyz * fma(_1184, _1184, -(_1174 * _1174)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1306, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1341.xxx, _1341.yyy, float3(params.facet_f0)) * _1360)) * _1415;
    float3 _1593 = fast::normalize(_1007 + frame.lightDirection.xyz);
    float _1535 = fast::clamp(dot(_1001, frame.lightDirection.xyz), 0.0, 1.0);
    float _1539 = fast::clamp(dot(_1001, _1593), 0.0, 1.0);
    float3 _1631 = cross(_1001, _1593);
    float _1634 = _1539 * params.facet_alpha;
    float _1643 = params.facet_alpha / fma(_1634, _1634, dot(_1631, _1631));
    float _1656 = params.facet_alpha * params.facet_alpha;
    float _1662 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1666 = sqrt(fma(_1302 * _1302, _1662, _1656));
    float _1689 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1593), 0.0, 1.0);
    float _1692 = _1689 * _1689;
    float3 _1700 = float3(1.0) - float3(params.facet_f0);
    float3 _1569 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float _1770 = _1440 * _1440;
    float _1790 = 8192.0 * fma(-_1535, _1302, _1535 + _1302);
    float _1794 = 1.0 / (_1770 * _1790);
    float _1801 = 2048.0 * _1770;
    float3 _1870 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1873 = dot(_1870, _1870);
    float3 _1878 = _1870 * rsqrt(fast::max(_1873, 9.9999999392252902907785028219223e-09));
    float _1882 = _1873 * float(frame.punctualLights[0].positionFalloff.w);
    float _1887 = fast::clamp(fma(-_1882, _1882, 1.0), 0.0, 1.0);
    float _1906 = fast::clamp(fma(dot(-_1878, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1915 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1887 * _1887) / fast::max(_1873, 9.9999997473787516355514526367188e-05)) * _1906) * _1906);
    float3 _2053 = fast::normalize(_1007 + _1878);
    float _1995 = fast::clamp(dot(_1001, _1878), 0.0, 1.0);
    float _1999 = fast::clamp(dot(_1001, _2053), 0.0, 1.0);
    float3 _2091 = cross(_1001, _2053);
    float _2094 = _1999 * params.facet_alpha;
    float _2103 = params.facet_alpha / fma(_2094, _2094, dot(_2091, _2091));
    float _2149 = 1.0 - fast::clamp(dot(_1878, _2053), 0.0, 1.0);
    float _2152 = _2149 * _2149;
    float _2250 = 8192.0 * fma(-_1995, _1302, _1995 + _1302);
    float _2254 = 1.0 / (_1770 * _2250);
    float3 _2295 = (fma(facet_environment.sample(facet_environmentSmplr, _1306, level(_1440 * 4.0)).xyz, _1447 * _1413, _1433) + (fast::min(fma((float3(params.facet_f0) + (_1700 * ((_1692 * _1692) * _1689))) * (((_1643 * _1643) * 0.3183098733425140380859375) * (0.5 / fma(_1535, _1666, _1302 * sqrt(fma(_1535 * _1535, _1662, _1656))))), _1360, _1569) * ((frame.lightColor.xyz * _1535) * _1415), float3(65504.0)) + fast::min((_1447 * ((((fma(_1794, _1790, 2.0) * pow(fast::max(fma(-_1539, _1539, 1.0), 0.0), 0.5 * (_1794 * _1790))) * 0.15915493667125701904296875) * (_1535 * (_1794 * _1801))) * _1417)) * frame.lightColor.xyz, float3(65504.0)))) + (fast::min(fma((float3(params.facet_f0) + (_1700 * ((_2152 * _2152) * _2149))) * (((_2103 * _2103) * 0.3183098733425140380859375) * (0.5 / fma(_1995, _1666, _1302 * sqrt(fma(_1995 * _1995, _1662, _1656))))), _1360, _1569) * ((_1915 * _1995) * _1415), float3(65504.0)) + fast::min((_1447 * ((((fma(_2254, _2250, 2.0) * pow(fast::max(fma(-_1999, _1999, 1.0), 0.0), 0.5 * (_2254 * _2250))) * 0.15915493667125701904296875) * (_1995 * (_2254 * _1801))) * _1417)) * _1915, float3(65504.0)));
    float3 _2330 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2333 = dot(_2330, _2330);
    float3 _2338 = _2330 * rsqrt(fast::max(_2333, 9.9999999392252902907785028219223e-09));
    float _2342 = _2333 * float(frame.punctualLights[1].positionFalloff.w);
    float _2347 = fast::clamp(fma(-_2342, _2342, 1.0), 0.0, 1.0);
    float _2366 = fast::clamp(fma(dot(-_2338, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2375 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2347 * _2347) / fast::max(_2333, 9.9999997473787516355514526367188e-05)) * _2366) * _2366);
    float3 _2513 = fast::normalize(_1007 + _2338);
    float _2455 = fast::clamp(dot(_1001, _2338), 0.0, 1.0);
    float _2459 = fast::clamp(dot(_1001, _2513), 0.0, 1.0);
    float3 _2551 = cross(_1001, _2513);
    float _2554 = _2459 * params.facet_alpha;
    float _2563 = params.facet_alpha / fma(_2554, _2554, dot(_2551, _2551));
    float _2609 = 1.0 - fast::clamp(dot(_2338, _2513), 0.0, 1.0);
    float _2612 = _2609 * _2609;
    float _2710 = 8192.0 * fma(-_2455, _1302, _2455 + _1302);
    float _2714 = 1.0 / (_1770 * _2710);
    out.fragColor = float4(_2295 + (fast::min(fma((float3(params.facet_f0) + (_1700 * ((_2612 * _2612) * _2609))) * (((_2563 * _2563) * 0.3183098733425140380859375) * (0.5 / fma(_2455, _1666, _1302 * sqrt(fma(_2455 * _2455, _1662, _1656))))), _1360, _1569) * ((_2375 * _2455) * _1415), float3(65504.0)) + fast::min((_1447 * ((((fma(_2714, _2710, 2.0) * pow(fast::max(fma(-_2459, _2459, 1.0), 0.0), 0.5 * (_2714 * _2710))) * 0.15915493667125701904296875) * (_2455 * (_2714 * _1801))) * _1417)) * _2375, float3(65504.0))), 1.0);
    return out;
}

