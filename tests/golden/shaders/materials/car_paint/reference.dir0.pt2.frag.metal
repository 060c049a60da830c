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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    float3 _959 = fast::normalize(in.v_normal);
    float3 _965 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1249 = fast::max(dot(_959, _965), 9.9999997473787516355514526367188e-05);
    float3 _1253 = reflect(-_965, _959);
    float4 _1288 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1249, params.facet_perceptualRoughness), level(0.0));
    float3 _1307 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1288.y) - 1.0));
    float _1364 = 1.0 - _1249;
    float _1367 = _1364 * _1364;
    float _1374 = fma(0.959999978542327880859375, (_1367 * _1367) * _1364, 0.039999999105930328369140625);
    float _1344 = fma(-_1374, params.facet_clearCoat, 1.0);
    float3 _1413 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1416 = dot(_1413, _1413);
    float3 _1421 = _1413 * rsqrt(fast::max(_1416, 9.9999999392252902907785028219223e-09));
    float _1425 = _1416 * float(frame.punctualLights[0].positionFalloff.w);
    float _1430 = fast::clamp(fma(-_1425, _1425, 1.0), 0.0, 1.0);
    float _1449 = fast::clamp(fma(dot(-_1421, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1581 = fast::normalize(_965 + _1421);
    float _1514 = fast::clamp(dot(_959, _1421), 0.0, 1.0);
    float _1518 = fast::clamp(dot(_959, _1581), 0.0, 1.0);
    float _1522 = fast::clamp(dot(_1421, _1581), 0.0, 1.0);
    float _1619 = 4096.0 * params.facet_alpha;
    float3 _1637 = cross(_959, _1581) * 64.0;
    float _1639 = 64.0 * params.facet_alpha;
    float _1641 = _1639 * _1518;
    float _1644 = dot(_1637, _1637);
    float _1625 = _1619 / fma(_1641, _1641, _1644);
    float _1656 = params.facet_alpha * params.facet_alpha;
    float _1662 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1666 = sqrt(fma(_1249 * _1249, _1662, _1656));
    float _1689 = 1.0 - _1522;
    float _1692 = _1689 * _1689;
    float _1697 = (_1692 * _1692) * _1689;
    float3 _1700 = float3(1.0) - float3(params.facet_f0);
    float _1783 = 64.0 * params.facet_clearCoatAlpha;
    float _1785 = _1783 * _1518;
    float _1738 = 12.56637096405029296875 * fast::max(_1522 * _1522, 6.103515625e-05);
    float _1740 = 4096.0 * params.facet_clearCoatAlpha;
    float _1744 = _1740 / (fma(_1785, _1785, _1644) * _1738);
    float _1761 = 0.959999978542327880859375 * params.facet_clearCoat;
    float3 _1850 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1853 = dot(_1850, _1850);
    float3 _1858 = _1850 * rsqrt(fast::max(_1853, 9.9999999392252902907785028219223e-09));
    float _1862 = _1853 * float(frame.punctualLights[1].positionFalloff.w);
    float _1867 = fast::clamp(fma(-_1862, _1862, 1.0), 0.0, 1.0);
    float _1886 = fast::clamp(fma(dot(-_1858, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2018 = fast::normalize(_965 + _1858);
    float _1951 = fast::clamp(dot(_959, _1858), 0.0, 1.0);
    float _1955 = fast::clamp(dot(_959, _2018), 0.0, 1.0);
    float _1959 = fast::clamp(dot(_1858, _2018), 0.0, 1.0);
    float3 _2074 = cross(_959, _2018) * 64.0;
    float _2078 = _1639 * _1955;
    float _2081 = dot(_2074, _2074);
    float _2062 = _1619 / fma(_2078, _2078, _2081);
    float _2126 = 1.0 - _1959;
    float _2129 = _2126 * _2126;
    float _2134 = (_2129 * _2129) * _2126;
    float _2222 = _1783 * _1955;
    float _2175 = 12.56637096405029296875 * fast::max(_1959 * _1959, 6.103515625e-05);
    float _2181 = _1740 / (fma(_2222, _2222, _2081) * _2175);
    float3 _2252 = (mix(facet_environment.sample(facet_environmentSmplr, _1253, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1288.xxx, _1288.yyy, float3(params.facet_f0)) * _1307), facet_environment.sample(facet_environmentSmplr, _1253, level(params.facet_clearCoatLod)).xyz, float3(_1374 * params.facet_clearCoat)) + fast::min(fast::min(((((float3(params.facet_f0) + (_1700 * _1697)) * (((_1625 * _1625) * 0.3183098733425140380859375) * (0.5 / fma(_1514, _1666, _1249 * sqrt(fma(_1514 * _1514, _1662, _1656)))))) * _1307) * _1344) + float3((_1744 * (_1744 * _1738)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1761 * _1697)), float3(65504.0)) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1430 * _1430) / fast::max(_1416, 9.9999997473787516355514526367188e-05)) * _1449) * _1449)) * _1514), float3(65504.0))) + fast::min(fast::min(((((float3(params.facet_f0) + (_1700 * _2134)) * (((_2062 * _2062) * 0.3183098733425140380859375) * (0.5 / fma(_1951, _1666, _1249 * sqrt(fma(_1951 * _1951, _1662, _1656)))))) * _1307) * _1344) + float3((_2181 * (_2181 * _2175)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1761 * _2134)), float3(65504.0)) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1867 * _1867) / fast::max(_1853, 9.9999997473787516355514526367188e-05)) * _1886) * _1886)) * _1951), float3(65504.0));
    out.fragColor = float4(_2252, 1.0);
    return out;
}

