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
    float _1072 = fast::max(dot(_778, _784), 9.9999997473787516355514526367188e-05);
    float4 _1111 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1072, params.facet_perceptualRoughness), level(0.0));
    float3 _1130 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1111.y) - 1.0));
    float3 _1255 = fast::normalize(_784 + frame.lightDirection.xyz);
    float _1200 = fast::clamp(dot(_778, frame.lightDirection.xyz), 0.0, 1.0);
    float _1293 = 4096.0 * params.facet_alpha;
    float4 _1317 = float4(cross(_778, _1255), params.facet_alpha * fast::clamp(dot(_778, _1255), 0.0, 1.0)) * 64.0;
    float _1299 = _1293 / dot(_1317, _1317);
    float _1328 = params.facet_alpha * params.facet_alpha;
    float _1334 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1338 = sqrt(fma(_1072 * _1072, _1334, _1328));
    float _1361 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1255), 0.0, 1.0);
    float _1364 = _1361 * _1361;
    float3 _1372 = float3(1.0) - float3(params.facet_f0);
    float3 _1429 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1432 = dot(_1429, _1429);
    float3 _1437 = _1429 * rsqrt(fast::max(_1432, 9.9999999392252902907785028219223e-09));
    float _1441 = _1432 * float(frame.punctualLights[0].positionFalloff.w);
    float _1446 = fast::clamp(fma(-_1441, _1441, 1.0), 0.0, 1.0);
    float _1465 = fast::clamp(fma(dot(-_1437, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1580 = fast::normalize(_784 + _1437);
    float _1525 = fast::clamp(dot(_778, _1437), 0.0, 1.0);
    float4 _1642 = float4(cross(_778, _1580), params.facet_alpha * fast::clamp(dot(_778, _1580), 0.0, 1.0)) * 64.0;
    float _1624 = _1293 / dot(_1642, _1642);
    float _1686 = 1.0 - fast::clamp(dot(_1437, _1580), 0.0, 1.0);
    float _1689 = _1686 * _1686;
    float3 _1754 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1757 = dot(_1754, _1754);
    float3 _1762 = _1754 * rsqrt(fast::max(_1757, 9.9999999392252902907785028219223e-09));
    float _1766 = _1757 * float(frame.punctualLights[1].positionFalloff.w);
    float _1771 = fast::clamp(fma(-_1766, _1766, 1.0), 0.0, 1.0);
    float _1790 = fast::clamp(fma(dot(-_1762, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1905 = fast::normalize(_784 + _1762);
    float _1850 = fast::clamp(dot(_778, _1762), 0.0, 1.0);
    float4 _1967 = float4(cross(_778, _1905), params.facet_alpha * fast::clamp(dot(_778, _1905), 0.0, 1.0)) * 64.0;
    float _1949 = _1293 / dot(_1967, _1967);
    float _2011 = 1.0 - fast::clamp(dot(_1762, _1905), 0.0, 1.0);
    float _2014 = _2011 * _2011;
    float3 _2044 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_784, _778), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1111.xxx, _1111.yyy, float3(params.facet_f0)) * _1130, fast::min((((float3(params.facet_f0) + (_1372 * ((_1364 * _1364) * _1361))) * (((_1299 * _1299) * 0.3183098733425140380859375) * (0.5 / fma(_1200, _1338, _1072 * sqrt(fma(_1200 * _1200, _1334, _1328)))))) * _1130) * (frame.lightColor.xyz * _1200), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1372 * ((_1689 * _1689) * _1686))) * (((_1624 * _1624) * 0.3183098733425140380859375) * (0.5 / fma(_1525, _1338, _1072 * sqrt(fma(_1525 * _1525, _1334, _1328)))))) * _1130) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1446 * _1446) / fast::max(_1432, 9.9999997473787516355514526367188e-05)) * _1465) * _1465)) * _1525), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1372 * ((_2014 * _2014) * _2011))) * (((_1949 * _1949) * 0.3183098733425140380859375) * (0.5 / fma(_1850, _1338, _1072 * sqrt(fma(_1850 * _1850, _1334, _1328)))))) * _1130) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1771 * _1771) / fast::max(_1757, 9.9999997473787516355514526367188e-05)) * _1790) * _1790)) * _1850), float3(65504.0));
    out.fragColor = float4(_2044, 1.0);
    return out;
}

