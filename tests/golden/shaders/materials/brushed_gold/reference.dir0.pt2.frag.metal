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
    float3 _756 = fast::normalize(in.v_normal);
    float3 _762 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1032 = fast::max(dot(_756, _762), 9.9999997473787516355514526367188e-05);
    float4 _1071 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1032, params.facet_perceptualRoughness), level(0.0));
    float3 _1090 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1071.y) - 1.0));
    float3 _1141 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1144 = dot(_1141, _1141);
    float3 _1149 = _1141 * rsqrt(fast::max(_1144, 9.9999999392252902907785028219223e-09));
    float _1153 = _1144 * float(frame.punctualLights[0].positionFalloff.w);
    float _1158 = fast::clamp(fma(-_1153, _1153, 1.0), 0.0, 1.0);
    float _1177 = fast::clamp(fma(dot(-_1149, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1292 = fast::normalize(_762 + _1149);
    float _1237 = fast::clamp(dot(_756, _1149), 0.0, 1.0);
    float3 _1330 = cross(_756, _1292);
    float _1333 = fast::clamp(dot(_756, _1292), 0.0, 1.0) * params.facet_alpha;
    float _1342 = params.facet_alpha / fma(_1333, _1333, dot(_1330, _1330));
    float _1355 = params.facet_alpha * params.facet_alpha;
    float _1361 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1365 = sqrt(fma(_1032 * _1032, _1361, _1355));
    float _1388 = 1.0 - fast::clamp(dot(_1149, _1292), 0.0, 1.0);
    float _1391 = _1388 * _1388;
    float3 _1399 = float3(1.0) - float3(params.facet_f0);
    float3 _1456 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1459 = dot(_1456, _1456);
    float3 _1464 = _1456 * rsqrt(fast::max(_1459, 9.9999999392252902907785028219223e-09));
    float _1468 = _1459 * float(frame.punctualLights[1].positionFalloff.w);
    float _1473 = fast::clamp(fma(-_1468, _1468, 1.0), 0.0, 1.0);
    float _1492 = fast::clamp(fma(dot(-_1464, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1607 = fast::normalize(_762 + _1464);
    float _1552 = fast::clamp(dot(_756, _1464), 0.0, 1.0);
    float3 _1645 = cross(_756, _1607);
    float _1648 = fast::clamp(dot(_756, _1607), 0.0, 1.0) * params.facet_alpha;
    float _1657 = params.facet_alpha / fma(_1648, _1648, dot(_1645, _1645));
    float _1703 = 1.0 - fast::clamp(dot(_1464, _1607), 0.0, 1.0);
    float _1706 = _1703 * _1703;
    float3 _1736 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_762, _756), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1071.xxx, _1071.yyy, float3(params.facet_f0)) * _1090, fast::min((((float3(params.facet_f0) + (_1399 * ((_1391 * _1391) * _1388))) * (((_1342 * _1342) * 0.3183098733425140380859375) * (0.5 / fma(_1237, _1365, _1032 * sqrt(fma(_1237 * _1237, _1361, _1355)))))) * _1090) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1158 * _1158) / fast::max(_1144, 9.9999997473787516355514526367188e-05)) * _1177) * _1177)) * _1237), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1399 * ((_1706 * _1706) * _1703))) * (((_1657 * _1657) * 0.3183098733425140380859375) * (0.5 / fma(_1552, _1365, _1032 * sqrt(fma(_1552 * _1552, _1361, _1355)))))) * _1090) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1473 * _1473) / fast::max(_1459, 9.9999997473787516355514526367188e-05)) * _1492) * _1492)) * _1552), float3(65504.0));
    out.fragColor = float4(_1736, 1.0);
    return out;
}

