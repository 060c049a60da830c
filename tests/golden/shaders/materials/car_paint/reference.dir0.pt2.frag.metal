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
    float3 _948 = fast::normalize(in.v_normal);
    float3 _954 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1237 = fast::max(dot(_948, _954), 9.9999997473787516355514526367188e-05);
    float3 _1241 = reflect(-_954, _948);
    float4 _1276 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1237, params.facet_perceptualRoughness), level(0.0));
    float3 _1295 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1276.y) - 1.0));
    float _1350 = 1.0 - _1237;
    float _1353 = _1350 * _1350;
    float _1360 = fma(0.959999978542327880859375, (_1353 * _1353) * _1350, 0.039999999105930328369140625);
    float _1365 = fast::clamp(params.coat, 0.0, 1.0);
    float _1332 = fma(-_1360, _1365, 1.0);
    float _1370 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1413 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1416 = dot(_1413, _1413);
    float3 _1421 = _1413 * rsqrt(fast::max(_1416, 9.9999999392252902907785028219223e-09));
    float _1425 = _1416 * float(frame.punctualLights[0].positionFalloff.w);
    float _1430 = fast::clamp(fma(-_1425, _1425, 1.0), 0.0, 1.0);
    float _1449 = fast::clamp(fma(dot(-_1421, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1581 = fast::normalize(_954 + _1421);
    float _1515 = fast::clamp(dot(_948, _1421), 0.0, 1.0);
    float _1519 = fast::clamp(dot(_948, _1581), 0.0, 1.0);
    float _1523 = fast::clamp(dot(_1421, _1581), 0.0, 1.0);
    float3 _1619 = cross(_948, _1581);
    float _1622 = _1519 * params.facet_alpha;
    float _1626 = dot(_1619, _1619);
    float _1631 = params.facet_alpha / fma(_1622, _1622, _1626);
    float _1644 = params.facet_alpha * params.facet_alpha;
    float _1650 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1654 = sqrt(fma(_1237 * _1237, _1650, _1644));
    float _1677 = 1.0 - _1523;
    float _1680 = _1677 * _1677;
    float _1685 = (_1680 * _1680) * _1677;
    float3 _1688 = float3(1.0) - float3(params.facet_f0);
    float3 _1541 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1430 * _1430) / fast::max(_1416, 9.9999997473787516355514526367188e-05)) * _1449) * _1449)) * _1515;
    float _1722 = _1370 * _1370;
    float _1728 = _1519 * _1722;
    float _1739 = fast::max(_1523 * _1523, 6.103515625e-05);
    float _1742 = 2048.0 * _1722;
    float _1747 = _1742 / (fma(_1728, _1728, _1626) * (_1739 * 25735.927734375));
    float3 _1844 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1847 = dot(_1844, _1844);
    float3 _1852 = _1844 * rsqrt(fast::max(_1847, 9.9999999392252902907785028219223e-09));
    float _1856 = _1847 * float(frame.punctualLights[1].positionFalloff.w);
    float _1861 = fast::clamp(fma(-_1856, _1856, 1.0), 0.0, 1.0);
    float _1880 = fast::clamp(fma(dot(-_1852, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2012 = fast::normalize(_954 + _1852);
    float _1946 = fast::clamp(dot(_948, _1852), 0.0, 1.0);
    float _1950 = fast::clamp(dot(_948, _2012), 0.0, 1.0);
    float _1954 = fast::clamp(dot(_1852, _2012), 0.0, 1.0);
    float3 _2050 = cross(_948, _2012);
    float _2053 = _1950 * params.facet_alpha;
    float _2057 = dot(_2050, _2050);
    float _2062 = params.facet_alpha / fma(_2053, _2053, _2057);
    float _2108 = 1.0 - _1954;
    float _2111 = _2108 * _2108;
    float _2116 = (_2111 * _2111) * _2108;
    float3 _1972 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1861 * _1861) / fast::max(_1847, 9.9999997473787516355514526367188e-05)) * _1880) * _1880)) * _1946;
    float _2159 = _1950 * _1722;
    float _2170 = fast::max(_1954 * _1954, 6.103515625e-05);
    float _2178 = _1742 / (fma(_2159, _2159, _2057) * (_2170 * 25735.927734375));
    float3 _2240 = (mix(facet_environment.sample(facet_environmentSmplr, _1241, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1276.xxx, _1276.yyy, float3(params.facet_f0)) * _1295), facet_environment.sample(facet_environmentSmplr, _1241, level(_1370 * 4.0)).xyz, float3(_1360 * _1365)) + fast::min(fma(((float3(params.facet_f0) + (_1688 * _1685)) * (((_1631 * _1631) * 0.3183098733425140380859375) * (0.5 / fma(_1515, _1654, _1237 * sqrt(fma(_1515 * _1515, _1650, _1644)))))) * _1295, _1541 * _1332, _1541 * ((_1747 * (_1747 * (12.56637096405029296875 * _1739))) * (fma(0.959999978542327880859375, _1685, 0.039999999105930328369140625) * _1365))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1688 * _2116)) * (((_2062 * _2062) * 0.3183098733425140380859375) * (0.5 / fma(_1946, _1654, _1237 * sqrt(fma(_1946 * _1946, _1650, _1644)))))) * _1295, _1972 * _1332, _1972 * ((_2178 * (_2178 * (12.56637096405029296875 * _2170))) * (fma(0.959999978542327880859375, _2116, 0.039999999105930328369140625) * _1365))), float3(65504.0));
    out.fragColor = float4(_2240, 1.0);
    return out;
}

