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
    float3 _952 = fast::normalize(in.v_normal);
    float3 _958 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1241 = fast::max(dot(_952, _958), 9.9999997473787516355514526367188e-05);
    float3 _1245 = reflect(-_958, _952);
    float4 _1280 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1241, params.facet_perceptualRoughness), level(0.0));
    float3 _1299 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1280.y) - 1.0));
    float _1357 = 1.0 - _1241;
    float _1360 = _1357 * _1357;
    float _1367 = fma(0.959999978542327880859375, (_1360 * _1360) * _1357, 0.039999999105930328369140625);
    float _1372 = fast::clamp(params.coat, 0.0, 1.0);
    float _1339 = fma(-_1367, _1372, 1.0);
    float _1377 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1423 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1426 = dot(_1423, _1423);
    float3 _1431 = _1423 * rsqrt(fast::max(_1426, 9.9999999392252902907785028219223e-09));
    float _1435 = _1426 * float(frame.punctualLights[0].positionFalloff.w);
    float _1440 = fast::clamp(fma(-_1435, _1435, 1.0), 0.0, 1.0);
    float _1459 = fast::clamp(fma(dot(-_1431, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1591 = fast::normalize(_958 + _1431);
    float _1525 = fast::clamp(dot(_952, _1431), 0.0, 1.0);
    float _1529 = fast::clamp(dot(_952, _1591), 0.0, 1.0);
    float _1533 = fast::clamp(dot(_1431, _1591), 0.0, 1.0);
    float3 _1629 = cross(_952, _1591);
    float _1632 = _1529 * params.facet_alpha;
    float _1636 = dot(_1629, _1629);
    float _1641 = params.facet_alpha / fma(_1632, _1632, _1636);
    float _1654 = params.facet_alpha * params.facet_alpha;
    float _1660 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1664 = sqrt(fma(_1241 * _1241, _1660, _1654));
    float _1687 = 1.0 - _1533;
    float _1690 = _1687 * _1687;
    float _1695 = (_1690 * _1690) * _1687;
    float3 _1698 = float3(1.0) - float3(params.facet_f0);
    float3 _1551 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1440 * _1440) / fast::max(_1426, 9.9999997473787516355514526367188e-05)) * _1459) * _1459)) * _1525;
    float _1732 = _1377 * _1377;
    float _1738 = _1529 * _1732;
    float _1749 = fast::max(_1533 * _1533, 6.103515625e-05);
    float _1752 = 2048.0 * _1732;
    float _1757 = _1752 / (fma(_1738, _1738, _1636) * (_1749 * 25735.927734375));
    float3 _1854 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1857 = dot(_1854, _1854);
    float3 _1862 = _1854 * rsqrt(fast::max(_1857, 9.9999999392252902907785028219223e-09));
    float _1866 = _1857 * float(frame.punctualLights[1].positionFalloff.w);
    float _1871 = fast::clamp(fma(-_1866, _1866, 1.0), 0.0, 1.0);
    float _1890 = fast::clamp(fma(dot(-_1862, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2022 = fast::normalize(_958 + _1862);
    float _1956 = fast::clamp(dot(_952, _1862), 0.0, 1.0);
    float _1960 = fast::clamp(dot(_952, _2022), 0.0, 1.0);
    float _1964 = fast::clamp(dot(_1862, _2022), 0.0, 1.0);
    float3 _2060 = cross(_952, _2022);
    float _2063 = _1960 * params.facet_alpha;
    float _2067 = dot(_2060, _2060);
    float _2072 = params.facet_alpha / fma(_2063, _2063, _2067);
    float _2118 = 1.0 - _1964;
    float _2121 = _2118 * _2118;
    float _2126 = (_2121 * _2121) * _2118;
    float3 _1982 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1871 * _1871) / fast::max(_1857, 9.9999997473787516355514526367188e-05)) * _1890) * _1890)) * _1956;
    float _2169 = _1960 * _1732;
    float _2180 = fast::max(_1964 * _1964, 6.103515625e-05);
    float _2188 = _1752 / (fma(_2169, _2169, _2067) * (_2180 * 25735.927734375));
    float3 _2250 = (mix(facet_environment.sample(facet_environmentSmplr, _1245, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1280.xxx, _1280.yyy, float3(params.facet_f0)) * _1299), facet_environment.sample(facet_environmentSmplr, _1245, level(_1377 * (4.0 * (2.0 - _1377)))).xyz, float3(_1367 * _1372)) + fast::min(fma(((float3(params.facet_f0) + (_1698 * _1695)) * (((_1641 * _1641) * 0.3183098733425140380859375) * (0.5 / fma(_1525, _1664, _1241 * sqrt(fma(_1525 * _1525, _1660, _1654)))))) * _1299, _1551 * _1339, _1551 * ((_1757 * (_1757 * (12.56637096405029296875 * _1749))) * (fma(0.959999978542327880859375, _1695, 0.039999999105930328369140625) * _1372))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1698 * _2126)) * (((_2072 * _2072) * 0.3183098733425140380859375) * (0.5 / fma(_1956, _1664, _1241 * sqrt(fma(_1956 * _1956, _1660, _1654)))))) * _1299, _1982 * _1339, _1982 * ((_2188 * (_2188 * (12.56637096405029296875 * _2180))) * (fma(0.959999978542327880859375, _2126, 0.039999999105930328369140625) * _1372))), float3(65504.0));
    out.fragColor = float4(_2250, 1.0);
    return out;
}

