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
    float _1240 = fast::max(dot(_948, _954), 9.9999997473787516355514526367188e-05);
    float3 _1244 = reflect(-_954, _948);
    float4 _1279 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1240, params.facet_perceptualRoughness), level(0.0));
    float3 _1298 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1279.y) - 1.0));
    float _1353 = 1.0 - _1240;
    float _1356 = _1353 * _1353;
    float _1363 = fma(0.959999978542327880859375, (_1356 * _1356) * _1353, 0.039999999105930328369140625);
    float _1368 = fast::clamp(params.coat, 0.0, 1.0);
    float _1335 = fma(-_1363, _1368, 1.0);
    float _1373 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1416 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1419 = dot(_1416, _1416);
    float3 _1424 = _1416 * rsqrt(fast::max(_1419, 9.9999999392252902907785028219223e-09));
    float _1428 = _1419 * float(frame.punctualLights[0].positionFalloff.w);
    float _1433 = fast::clamp(fma(-_1428, _1428, 1.0), 0.0, 1.0);
    float _1452 = fast::clamp(fma(dot(-_1424, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1584 = fast::normalize(_954 + _1424);
    float _1518 = fast::clamp(dot(_948, _1424), 0.0, 1.0);
    float _1522 = fast::clamp(dot(_948, _1584), 0.0, 1.0);
    float _1526 = fast::clamp(dot(_1424, _1584), 0.0, 1.0);
    float3 _1622 = cross(_948, _1584);
    float _1625 = _1522 * params.facet_alpha;
    float _1629 = dot(_1622, _1622);
    float _1634 = params.facet_alpha / fma(_1625, _1625, _1629);
    float _1647 = params.facet_alpha * params.facet_alpha;
    float _1653 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1657 = sqrt(fma(_1240 * _1240, _1653, _1647));
    float _1680 = 1.0 - _1526;
    float _1683 = _1680 * _1680;
    float _1688 = (_1683 * _1683) * _1680;
    float3 _1691 = float3(1.0) - float3(params.facet_f0);
    float3 _1544 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1433 * _1433) / fast::max(_1419, 9.9999997473787516355514526367188e-05)) * _1452) * _1452)) * _1518;
    float _1725 = _1373 * _1373;
    float _1731 = _1522 * _1725;
    float _1742 = fast::max(_1526 * _1526, 6.103515625e-05);
    float _1745 = 2048.0 * _1725;
    float _1750 = _1745 / (fma(_1731, _1731, _1629) * (_1742 * 25735.927734375));
    float3 _1847 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1850 = dot(_1847, _1847);
    float3 _1855 = _1847 * rsqrt(fast::max(_1850, 9.9999999392252902907785028219223e-09));
    float _1859 = _1850 * float(frame.punctualLights[1].positionFalloff.w);
    float _1864 = fast::clamp(fma(-_1859, _1859, 1.0), 0.0, 1.0);
    float _1883 = fast::clamp(fma(dot(-_1855, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2015 = fast::normalize(_954 + _1855);
    float _1949 = fast::clamp(dot(_948, _1855), 0.0, 1.0);
    float _1953 = fast::clamp(dot(_948, _2015), 0.0, 1.0);
    float _1957 = fast::clamp(dot(_1855, _2015), 0.0, 1.0);
    float3 _2053 = cross(_948, _2015);
    float _2056 = _1953 * params.facet_alpha;
    float _2060 = dot(_2053, _2053);
    float _2065 = params.facet_alpha / fma(_2056, _2056, _2060);
    float _2111 = 1.0 - _1957;
    float _2114 = _2111 * _2111;
    float _2119 = (_2114 * _2114) * _2111;
    float3 _1975 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1864 * _1864) / fast::max(_1850, 9.9999997473787516355514526367188e-05)) * _1883) * _1883)) * _1949;
    float _2162 = _1953 * _1725;
    float _2173 = fast::max(_1957 * _1957, 6.103515625e-05);
    float _2181 = _1745 / (fma(_2162, _2162, _2060) * (_2173 * 25735.927734375));
    float3 _2243 = (mix(facet_environment.sample(facet_environmentSmplr, _1244, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1279.xxx, _1279.yyy, float3(params.facet_f0)) * _1298), facet_environment.sample(facet_environmentSmplr, _1244, level(_1373 * 4.0)).xyz, float3(_1363 * _1368)) + fast::min(fma(((float3(params.facet_f0) + (_1691 * _1688)) * (((_1634 * _1634) * 0.3183098733425140380859375) * (0.5 / fma(_1518, _1657, _1240 * sqrt(fma(_1518 * _1518, _1653, _1647)))))) * _1298, _1544 * _1335, _1544 * ((_1750 * (_1750 * (12.56637096405029296875 * _1742))) * (fma(0.959999978542327880859375, _1688, 0.039999999105930328369140625) * _1368))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1691 * _2119)) * (((_2065 * _2065) * 0.3183098733425140380859375) * (0.5 / fma(_1949, _1657, _1240 * sqrt(fma(_1949 * _1949, _1653, _1647)))))) * _1298, _1975 * _1335, _1975 * ((_2181 * (_2181 * (12.56637096405029296875 * _2173))) * (fma(0.959999978542327880859375, _2119, 0.039999999105930328369140625) * _1368))), float3(65504.0));
    out.fragColor = float4(_2243, 1.0);
    return out;
}

