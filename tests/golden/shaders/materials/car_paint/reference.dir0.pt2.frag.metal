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
    float3 _966 = fast::normalize(in.v_normal);
    float3 _972 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1255 = fast::max(dot(_966, _972), 9.9999997473787516355514526367188e-05);
    float3 _1259 = reflect(-_972, _966);
    float4 _1294 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, params.facet_perceptualRoughness), level(0.0));
    float3 _1313 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1294.y) - 1.0));
    float _1371 = 1.0 - _1255;
    float _1374 = _1371 * _1371;
    float _1381 = fma(0.959999978542327880859375, (_1374 * _1374) * _1371, 0.039999999105930328369140625);
    float _1386 = fast::clamp(params.coat, 0.0, 1.0);
    float _1353 = fma(-_1381, _1386, 1.0);
    float _1391 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1437 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1440 = dot(_1437, _1437);
    float3 _1445 = _1437 * rsqrt(fast::max(_1440, 9.9999999392252902907785028219223e-09));
    float _1449 = _1440 * float(frame.punctualLights[0].positionFalloff.w);
    float _1454 = fast::clamp(fma(-_1449, _1449, 1.0), 0.0, 1.0);
    float _1473 = fast::clamp(fma(dot(-_1445, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1605 = fast::normalize(_972 + _1445);
    float _1538 = fast::clamp(dot(_966, _1445), 0.0, 1.0);
    float _1542 = fast::clamp(dot(_966, _1605), 0.0, 1.0);
    float _1546 = fast::clamp(dot(_1445, _1605), 0.0, 1.0);
    float _1643 = 4096.0 * params.facet_alpha;
    float3 _1661 = cross(_966, _1605) * 64.0;
    float _1663 = 64.0 * params.facet_alpha;
    float _1665 = _1663 * _1542;
    float _1668 = dot(_1661, _1661);
    float _1649 = _1643 / fma(_1665, _1665, _1668);
    float _1680 = params.facet_alpha * params.facet_alpha;
    float _1686 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1690 = sqrt(fma(_1255 * _1255, _1686, _1680));
    float _1713 = 1.0 - _1546;
    float _1716 = _1713 * _1713;
    float _1721 = (_1716 * _1716) * _1713;
    float3 _1724 = float3(1.0) - float3(params.facet_f0);
    float _1756 = _1391 * _1391;
    float _1812 = 64.0 * _1756;
    float _1814 = _1812 * _1542;
    float _1766 = 12.56637096405029296875 * fast::max(_1546 * _1546, 6.103515625e-05);
    float _1768 = 4096.0 * _1756;
    float _1772 = _1768 / (fma(_1814, _1814, _1668) * _1766);
    float _1789 = 0.959999978542327880859375 * _1386;
    float3 _1880 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1883 = dot(_1880, _1880);
    float3 _1888 = _1880 * rsqrt(fast::max(_1883, 9.9999999392252902907785028219223e-09));
    float _1892 = _1883 * float(frame.punctualLights[1].positionFalloff.w);
    float _1897 = fast::clamp(fma(-_1892, _1892, 1.0), 0.0, 1.0);
    float _1916 = fast::clamp(fma(dot(-_1888, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2048 = fast::normalize(_972 + _1888);
    float _1981 = fast::clamp(dot(_966, _1888), 0.0, 1.0);
    float _1985 = fast::clamp(dot(_966, _2048), 0.0, 1.0);
    float _1989 = fast::clamp(dot(_1888, _2048), 0.0, 1.0);
    float3 _2104 = cross(_966, _2048) * 64.0;
    float _2108 = _1663 * _1985;
    float _2111 = dot(_2104, _2104);
    float _2092 = _1643 / fma(_2108, _2108, _2111);
    float _2156 = 1.0 - _1989;
    float _2159 = _2156 * _2156;
    float _2164 = (_2159 * _2159) * _2156;
    float _2257 = _1812 * _1985;
    float _2209 = 12.56637096405029296875 * fast::max(_1989 * _1989, 6.103515625e-05);
    float _2215 = _1768 / (fma(_2257, _2257, _2111) * _2209);
    float3 _2288 = (mix(facet_environment.sample(facet_environmentSmplr, _1259, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1294.xxx, _1294.yyy, float3(params.facet_f0)) * _1313), facet_environment.sample(facet_environmentSmplr, _1259, level(_1391 * (4.0 * (2.0 - _1391)))).xyz, float3(_1381 * _1386)) + fast::min(fast::min(((((float3(params.facet_f0) + (_1724 * _1721)) * (((_1649 * _1649) * 0.3183098733425140380859375) * (0.5 / fma(_1538, _1690, _1255 * sqrt(fma(_1538 * _1538, _1686, _1680)))))) * _1313) * _1353) + float3((_1772 * (_1772 * _1766)) * fma(0.039999999105930328369140625, _1386, _1789 * _1721)), float3(65504.0)) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1454 * _1454) / fast::max(_1440, 9.9999997473787516355514526367188e-05)) * _1473) * _1473)) * _1538), float3(65504.0))) + fast::min(fast::min(((((float3(params.facet_f0) + (_1724 * _2164)) * (((_2092 * _2092) * 0.3183098733425140380859375) * (0.5 / fma(_1981, _1690, _1255 * sqrt(fma(_1981 * _1981, _1686, _1680)))))) * _1313) * _1353) + float3((_2215 * (_2215 * _2209)) * fma(0.039999999105930328369140625, _1386, _1789 * _2164)), float3(65504.0)) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1897 * _1897) / fast::max(_1883, 9.9999997473787516355514526367188e-05)) * _1916) * _1916)) * _1981), float3(65504.0));
    out.fragColor = float4(_2288, 1.0);
    return out;
}

