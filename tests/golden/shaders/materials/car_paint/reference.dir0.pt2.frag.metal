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
    float _1364 = 1.0 - _1251;
    float _1367 = _1364 * _1364;
    float _1374 = fma(0.959999978542327880859375, (_1367 * _1367) * _1364, 0.039999999105930328369140625);
    float _1379 = fast::clamp(params.coat, 0.0, 1.0);
    float _1346 = fma(-_1374, _1379, 1.0);
    float _1384 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1427 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1430 = dot(_1427, _1427);
    float3 _1435 = _1427 * rsqrt(fast::max(_1430, 9.9999999392252902907785028219223e-09));
    float _1439 = _1430 * float(frame.punctualLights[0].positionFalloff.w);
    float _1444 = fast::clamp(fma(-_1439, _1439, 1.0), 0.0, 1.0);
    float _1463 = fast::clamp(fma(dot(-_1435, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1595 = fast::normalize(_968 + _1435);
    float _1529 = fast::clamp(dot(_962, _1435), 0.0, 1.0);
    float _1533 = fast::clamp(dot(_962, _1595), 0.0, 1.0);
    float _1537 = fast::clamp(dot(_1435, _1595), 0.0, 1.0);
    float _1634 = 4096.0 * params.facet_alpha;
    float3 _1653 = cross(_962, _1595) * 64.0;
    float _1656 = 64.0 * params.facet_alpha;
    float _1657 = _1533 * _1656;
    float _1660 = dot(_1653, _1653);
    float _1640 = _1634 / fma(_1657, _1657, _1660);
    float _1672 = params.facet_alpha * params.facet_alpha;
    float _1678 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1682 = sqrt(fma(_1251 * _1251, _1678, _1672));
    float _1705 = 1.0 - _1537;
    float _1708 = _1705 * _1705;
    float _1713 = (_1708 * _1708) * _1705;
    float3 _1716 = float3(1.0) - float3(params.facet_f0);
    float3 _1555 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1444 * _1444) / fast::max(_1430, 9.9999997473787516355514526367188e-05)) * _1463) * _1463)) * _1529;
    float _1752 = _1384 * _1384;
    float _1801 = 64.0 * _1752;
    float _1802 = _1533 * _1801;
    float _1762 = 12.56637096405029296875 * fast::max(_1537 * _1537, 6.103515625e-05);
    float _1764 = 4096.0 * _1752;
    float _1768 = _1764 / (fma(_1802, _1802, _1660) * _1762);
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
    float3 _2110 = cross(_962, _2052) * 64.0;
    float _2114 = _1990 * _1656;
    float _2117 = dot(_2110, _2110);
    float _2097 = _1634 / fma(_2114, _2114, _2117);
    float _2162 = 1.0 - _1994;
    float _2165 = _2162 * _2162;
    float _2170 = (_2165 * _2165) * _2162;
    float3 _2012 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1901 * _1901) / fast::max(_1887, 9.9999997473787516355514526367188e-05)) * _1920) * _1920)) * _1986;
    float _2259 = _1990 * _1801;
    float _2219 = 12.56637096405029296875 * fast::max(_1994 * _1994, 6.103515625e-05);
    float _2225 = _1764 / (fma(_2259, _2259, _2117) * _2219);
    float3 _2306 = (mix(facet_environment.sample(facet_environmentSmplr, _1255, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1290.xxx, _1290.yyy, float3(params.facet_f0)) * _1309), facet_environment.sample(facet_environmentSmplr, _1255, level(_1384 * 4.0)).xyz, float3(_1374 * _1379)) + fast::min(fma(((float3(params.facet_f0) + (_1716 * _1713)) * (((_1640 * _1640) * 0.3183098733425140380859375) * (0.5 / fma(_1529, _1682, _1251 * sqrt(fma(_1529 * _1529, _1678, _1672)))))) * _1309, _1555 * _1346, _1555 * ((_1768 * (_1768 * _1762)) * (fma(0.959999978542327880859375, _1713, 0.039999999105930328369140625) * _1379))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1716 * _2170)) * (((_2097 * _2097) * 0.3183098733425140380859375) * (0.5 / fma(_1986, _1682, _1251 * sqrt(fma(_1986 * _1986, _1678, _1672)))))) * _1309, _2012 * _1346, _2012 * ((_2225 * (_2225 * _2219)) * (fma(0.959999978542327880859375, _2170, 0.039999999105930328369140625) * _1379))), float3(65504.0));
    out.fragColor = float4(_2306, 1.0);
    return out;
}

