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
    float3 _950 = fast::normalize(in.v_normal);
    float3 _956 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1239 = fast::max(dot(_950, _956), 9.9999997473787516355514526367188e-05);
    float3 _1243 = reflect(-_956, _950);
    float4 _1278 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1239, params.facet_perceptualRoughness), level(0.0));
    float3 _1297 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1278.y) - 1.0));
    float _1352 = 1.0 - _1239;
    float _1355 = _1352 * _1352;
    float _1362 = fma(0.959999978542327880859375, (_1355 * _1355) * _1352, 0.039999999105930328369140625);
    float _1367 = fast::clamp(params.coat, 0.0, 1.0);
    float _1334 = fma(-_1362, _1367, 1.0);
    float _1372 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1415 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1418 = dot(_1415, _1415);
    float3 _1423 = _1415 * rsqrt(fast::max(_1418, 9.9999999392252902907785028219223e-09));
    float _1427 = _1418 * float(frame.punctualLights[0].positionFalloff.w);
    float _1432 = fast::clamp(fma(-_1427, _1427, 1.0), 0.0, 1.0);
    float _1451 = fast::clamp(fma(dot(-_1423, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1583 = fast::normalize(_956 + _1423);
    float _1517 = fast::clamp(dot(_950, _1423), 0.0, 1.0);
    float _1521 = fast::clamp(dot(_950, _1583), 0.0, 1.0);
    float _1525 = fast::clamp(dot(_1423, _1583), 0.0, 1.0);
    float3 _1621 = cross(_950, _1583);
    float _1624 = _1521 * params.facet_alpha;
    float _1633 = params.facet_alpha / fma(_1624, _1624, dot(_1621, _1621));
    float _1646 = params.facet_alpha * params.facet_alpha;
    float _1652 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1656 = sqrt(fma(_1239 * _1239, _1652, _1646));
    float _1679 = 1.0 - _1525;
    float _1682 = _1679 * _1679;
    float _1687 = (_1682 * _1682) * _1679;
    float3 _1690 = float3(1.0) - float3(params.facet_f0);
    float3 _1543 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1432 * _1432) / fast::max(_1418, 9.9999997473787516355514526367188e-05)) * _1451) * _1451)) * _1517;
    float _1724 = _1372 * _1372;
    float3 _1728 = _1621 * 64.0;
    float _1731 = 64.0 * _1724;
    float _1732 = _1521 * _1731;
    float _1744 = 12.56637096405029296875 * fast::max(_1525 * _1525, 6.103515625e-05);
    float _1746 = 4096.0 * _1724;
    float _1750 = _1746 / (fma(_1732, _1732, dot(_1728, _1728)) * _1744);
    float3 _1847 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1850 = dot(_1847, _1847);
    float3 _1855 = _1847 * rsqrt(fast::max(_1850, 9.9999999392252902907785028219223e-09));
    float _1859 = _1850 * float(frame.punctualLights[1].positionFalloff.w);
    float _1864 = fast::clamp(fma(-_1859, _1859, 1.0), 0.0, 1.0);
    float _1883 = fast::clamp(fma(dot(-_1855, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2015 = fast::normalize(_956 + _1855);
    float _1949 = fast::clamp(dot(_950, _1855), 0.0, 1.0);
    float _1953 = fast::clamp(dot(_950, _2015), 0.0, 1.0);
    float _1957 = fast::clamp(dot(_1855, _2015), 0.0, 1.0);
    float3 _2053 = cross(_950, _2015);
    float _2056 = _1953 * params.facet_alpha;
    float _2065 = params.facet_alpha / fma(_2056, _2056, dot(_2053, _2053));
    float _2111 = 1.0 - _1957;
    float _2114 = _2111 * _2111;
    float _2119 = (_2114 * _2114) * _2111;
    float3 _1975 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1864 * _1864) / fast::max(_1850, 9.9999997473787516355514526367188e-05)) * _1883) * _1883)) * _1949;
    float3 _2160 = _2053 * 64.0;
    float _2164 = _1953 * _1731;
    float _2176 = 12.56637096405029296875 * fast::max(_1957 * _1957, 6.103515625e-05);
    float _2182 = _1746 / (fma(_2164, _2164, dot(_2160, _2160)) * _2176);
    float3 _2244 = (mix(facet_environment.sample(facet_environmentSmplr, _1243, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1278.xxx, _1278.yyy, float3(params.facet_f0)) * _1297), facet_environment.sample(facet_environmentSmplr, _1243, level(_1372 * 4.0)).xyz, float3(_1362 * _1367)) + fast::min(fma(((float3(params.facet_f0) + (_1690 * _1687)) * (((_1633 * _1633) * 0.3183098733425140380859375) * (0.5 / fma(_1517, _1656, _1239 * sqrt(fma(_1517 * _1517, _1652, _1646)))))) * _1297, _1543 * _1334, _1543 * ((_1750 * (_1750 * _1744)) * (fma(0.959999978542327880859375, _1687, 0.039999999105930328369140625) * _1367))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1690 * _2119)) * (((_2065 * _2065) * 0.3183098733425140380859375) * (0.5 / fma(_1949, _1656, _1239 * sqrt(fma(_1949 * _1949, _1652, _1646)))))) * _1297, _1975 * _1334, _1975 * ((_2182 * (_2182 * _2176)) * (fma(0.959999978542327880859375, _2119, 0.039999999105930328369140625) * _1367))), float3(65504.0));
    out.fragColor = float4(_2244, 1.0);
    return out;
}

