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
    float3 _760 = fast::normalize(in.v_normal);
    float3 _766 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1033 = fast::max(dot(_760, _766), 9.9999997473787516355514526367188e-05);
    float4 _1072 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1033, params.facet_perceptualRoughness), level(0.0));
    float3 _1091 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1072.y) - 1.0));
    float3 _1145 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1148 = dot(_1145, _1145);
    float3 _1153 = _1145 * rsqrt(fast::max(_1148, 9.9999999392252902907785028219223e-09));
    float _1157 = _1148 * float(frame.punctualLights[0].positionFalloff.w);
    float _1162 = fast::clamp(fma(-_1157, _1157, 1.0), 0.0, 1.0);
    float _1181 = fast::clamp(fma(dot(-_1153, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1296 = fast::normalize(_766 + _1153);
    float _1241 = fast::clamp(dot(_760, _1153), 0.0, 1.0);
    float3 _1334 = cross(_760, _1296);
    float _1337 = fast::clamp(dot(_760, _1296), 0.0, 1.0) * params.facet_alpha;
    float _1346 = params.facet_alpha / fma(_1337, _1337, dot(_1334, _1334));
    float _1359 = params.facet_alpha * params.facet_alpha;
    float _1365 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1369 = sqrt(fma(_1033 * _1033, _1365, _1359));
    float _1392 = 1.0 - fast::clamp(dot(_1153, _1296), 0.0, 1.0);
    float _1395 = _1392 * _1392;
    float3 _1403 = float3(1.0) - float3(params.facet_f0);
    float3 _1460 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1463 = dot(_1460, _1460);
    float3 _1468 = _1460 * rsqrt(fast::max(_1463, 9.9999999392252902907785028219223e-09));
    float _1472 = _1463 * float(frame.punctualLights[1].positionFalloff.w);
    float _1477 = fast::clamp(fma(-_1472, _1472, 1.0), 0.0, 1.0);
    float _1496 = fast::clamp(fma(dot(-_1468, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1611 = fast::normalize(_766 + _1468);
    float _1556 = fast::clamp(dot(_760, _1468), 0.0, 1.0);
    float3 _1649 = cross(_760, _1611);
    float _1652 = fast::clamp(dot(_760, _1611), 0.0, 1.0) * params.facet_alpha;
    float _1661 = params.facet_alpha / fma(_1652, _1652, dot(_1649, _1649));
    float _1707 = 1.0 - fast::clamp(dot(_1468, _1611), 0.0, 1.0);
    float _1710 = _1707 * _1707;
    float3 _1740 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_766, _760), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1072.xxx, _1072.yyy, float3(params.facet_f0)) * _1091, fast::min((((float3(params.facet_f0) + (_1403 * ((_1395 * _1395) * _1392))) * (((_1346 * _1346) * 0.3183098733425140380859375) * (0.5 / fma(_1241, _1369, _1033 * sqrt(fma(_1241 * _1241, _1365, _1359)))))) * _1091) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1162 * _1162) / fast::max(_1148, 9.9999997473787516355514526367188e-05)) * _1181) * _1181)) * _1241), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1403 * ((_1710 * _1710) * _1707))) * (((_1661 * _1661) * 0.3183098733425140380859375) * (0.5 / fma(_1556, _1369, _1033 * sqrt(fma(_1556 * _1556, _1365, _1359)))))) * _1091) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1477 * _1477) / fast::max(_1463, 9.9999997473787516355514526367188e-05)) * _1496) * _1496)) * _1556), float3(65504.0));
    out.fragColor = float4(_1740, 1.0);
    return out;
}

