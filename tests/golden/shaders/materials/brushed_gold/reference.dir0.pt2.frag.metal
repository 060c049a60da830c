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
    float3 _1163 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1166 = dot(_1163, _1163);
    float3 _1171 = _1163 * rsqrt(fast::max(_1166, 9.9999999392252902907785028219223e-09));
    float _1175 = _1166 * float(frame.punctualLights[0].positionFalloff.w);
    float _1180 = fast::clamp(fma(-_1175, _1175, 1.0), 0.0, 1.0);
    float _1199 = fast::clamp(fma(dot(-_1171, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1314 = fast::normalize(_784 + _1171);
    float _1259 = fast::clamp(dot(_778, _1171), 0.0, 1.0);
    float _1352 = 4096.0 * params.facet_alpha;
    float4 _1376 = float4(cross(_778, _1314), params.facet_alpha * fast::clamp(dot(_778, _1314), 0.0, 1.0)) * 64.0;
    float _1358 = _1352 / dot(_1376, _1376);
    float _1387 = params.facet_alpha * params.facet_alpha;
    float _1393 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1397 = sqrt(fma(_1051 * _1051, _1393, _1387));
    float _1420 = 1.0 - fast::clamp(dot(_1171, _1314), 0.0, 1.0);
    float _1423 = _1420 * _1420;
    float3 _1431 = float3(1.0) - float3(params.facet_f0);
    float3 _1488 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1491 = dot(_1488, _1488);
    float3 _1496 = _1488 * rsqrt(fast::max(_1491, 9.9999999392252902907785028219223e-09));
    float _1500 = _1491 * float(frame.punctualLights[1].positionFalloff.w);
    float _1505 = fast::clamp(fma(-_1500, _1500, 1.0), 0.0, 1.0);
    float _1524 = fast::clamp(fma(dot(-_1496, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1639 = fast::normalize(_784 + _1496);
    float _1584 = fast::clamp(dot(_778, _1496), 0.0, 1.0);
    float4 _1701 = float4(cross(_778, _1639), params.facet_alpha * fast::clamp(dot(_778, _1639), 0.0, 1.0)) * 64.0;
    float _1683 = _1352 / dot(_1701, _1701);
    float _1745 = 1.0 - fast::clamp(dot(_1496, _1639), 0.0, 1.0);
    float _1748 = _1745 * _1745;
    float3 _1778 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_784, _778), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1090.xxx, _1090.yyy, float3(params.facet_f0)) * _1109, fast::min((((float3(params.facet_f0) + (_1431 * ((_1423 * _1423) * _1420))) * (((_1358 * _1358) * 0.3183098733425140380859375) * (0.5 / fma(_1259, _1397, _1051 * sqrt(fma(_1259 * _1259, _1393, _1387)))))) * _1109) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1180 * _1180) / fast::max(_1166, 9.9999997473787516355514526367188e-05)) * _1199) * _1199)) * _1259), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1431 * ((_1748 * _1748) * _1745))) * (((_1683 * _1683) * 0.3183098733425140380859375) * (0.5 / fma(_1584, _1397, _1051 * sqrt(fma(_1584 * _1584, _1393, _1387)))))) * _1109) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1505 * _1505) / fast::max(_1491, 9.9999997473787516355514526367188e-05)) * _1524) * _1524)) * _1584), float3(65504.0));
    out.fragColor = float4(_1778, 1.0);
    return out;
}

