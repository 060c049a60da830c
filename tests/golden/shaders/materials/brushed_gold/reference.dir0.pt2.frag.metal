#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    float3 _778 = fast::normalize(in.v_normal);
    float3 _784 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1051 = fast::max(dot(_778, _784), 9.9999997473787516355514526367188e-05);
    float4 _1090 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1051, params.facet_perceptualRoughness), level(0.0));
    float3 _1109 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1090.y) - 1.0));
    float3 _1160 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1163 = dot(_1160, _1160);
    float3 _1168 = _1160 * rsqrt(fast::max(_1163, 9.9999999392252902907785028219223e-09));
    float _1172 = _1163 * float(frame.punctualLights[0].positionFalloff.w);
    float _1177 = fast::clamp(fma(-_1172, _1172, 1.0), 0.0, 1.0);
    float _1196 = fast::clamp(fma(dot(-_1168, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1311 = fast::normalize(_784 + _1168);
    float _1256 = fast::clamp(dot(_778, _1168), 0.0, 1.0);
    float _1350 = 4096.0 * params.facet_alpha;
    float3 _1369 = cross(_778, _1311) * 64.0;
    float _1372 = 64.0 * params.facet_alpha;
    float _1373 = fast::clamp(dot(_778, _1311), 0.0, 1.0) * _1372;
    float _1356 = _1350 / fma(_1373, _1373, dot(_1369, _1369));
    float _1388 = params.facet_alpha * params.facet_alpha;
    float _1394 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1398 = sqrt(fma(_1051 * _1051, _1394, _1388));
    float _1421 = 1.0 - fast::clamp(dot(_1168, _1311), 0.0, 1.0);
    float _1424 = _1421 * _1421;
    float3 _1432 = float3(1.0) - float3(params.facet_f0);
    float3 _1489 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1492 = dot(_1489, _1489);
    float3 _1497 = _1489 * rsqrt(fast::max(_1492, 9.9999999392252902907785028219223e-09));
    float _1501 = _1492 * float(frame.punctualLights[1].positionFalloff.w);
    float _1506 = fast::clamp(fma(-_1501, _1501, 1.0), 0.0, 1.0);
    float _1525 = fast::clamp(fma(dot(-_1497, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1640 = fast::normalize(_784 + _1497);
    float _1585 = fast::clamp(dot(_778, _1497), 0.0, 1.0);
    float3 _1698 = cross(_778, _1640) * 64.0;
    float _1702 = fast::clamp(dot(_778, _1640), 0.0, 1.0) * _1372;
    float _1685 = _1350 / fma(_1702, _1702, dot(_1698, _1698));
    float _1750 = 1.0 - fast::clamp(dot(_1497, _1640), 0.0, 1.0);
    float _1753 = _1750 * _1750;
    float3 _1783 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_784, _778), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1090.xxx, _1090.yyy, float3(params.facet_f0)) * _1109, fast::min((((float3(params.facet_f0) + (_1432 * ((_1424 * _1424) * _1421))) * (((_1356 * _1356) * 0.3183098733425140380859375) * (0.5 / fma(_1256, _1398, _1051 * sqrt(fma(_1256 * _1256, _1394, _1388)))))) * _1109) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1177 * _1177) / fast::max(_1163, 9.9999997473787516355514526367188e-05)) * _1196) * _1196)) * _1256), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1432 * ((_1753 * _1753) * _1750))) * (((_1685 * _1685) * 0.3183098733425140380859375) * (0.5 / fma(_1585, _1398, _1051 * sqrt(fma(_1585 * _1585, _1394, _1388)))))) * _1109) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1506 * _1506) / fast::max(_1492, 9.9999997473787516355514526367188e-05)) * _1525) * _1525)) * _1585), float3(65504.0));
    out.fragColor = float4(_1783, 1.0);
    return out;
}

