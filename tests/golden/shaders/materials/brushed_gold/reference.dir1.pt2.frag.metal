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
    float _1050 = fast::max(dot(_756, _762), 9.9999997473787516355514526367188e-05);
    float4 _1089 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1050, params.facet_perceptualRoughness), level(0.0));
    float3 _1108 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1089.y) - 1.0));
    float3 _1230 = fast::normalize(_762 + frame.lightDirection.xyz);
    float _1175 = fast::clamp(dot(_756, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1268 = cross(_756, _1230);
    float _1271 = fast::clamp(dot(_756, _1230), 0.0, 1.0) * params.facet_alpha;
    float _1280 = params.facet_alpha / fma(_1271, _1271, dot(_1268, _1268));
    float _1293 = params.facet_alpha * params.facet_alpha;
    float _1299 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1303 = sqrt(fma(_1050 * _1050, _1299, _1293));
    float _1326 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1230), 0.0, 1.0);
    float _1329 = _1326 * _1326;
    float3 _1337 = float3(1.0) - float3(params.facet_f0);
    float3 _1394 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1397 = dot(_1394, _1394);
    float3 _1402 = _1394 * rsqrt(fast::max(_1397, 9.9999999392252902907785028219223e-09));
    float _1406 = _1397 * float(frame.punctualLights[0].positionFalloff.w);
    float _1411 = fast::clamp(fma(-_1406, _1406, 1.0), 0.0, 1.0);
    float _1430 = fast::clamp(fma(dot(-_1402, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1545 = fast::normalize(_762 + _1402);
    float _1490 = fast::clamp(dot(_756, _1402), 0.0, 1.0);
    float3 _1583 = cross(_756, _1545);
    float _1586 = fast::clamp(dot(_756, _1545), 0.0, 1.0) * params.facet_alpha;
    float _1595 = params.facet_alpha / fma(_1586, _1586, dot(_1583, _1583));
    float _1641 = 1.0 - fast::clamp(dot(_1402, _1545), 0.0, 1.0);
    float _1644 = _1641 * _1641;
    float3 _1709 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1712 = dot(_1709, _1709);
    float3 _1717 = _1709 * rsqrt(fast::max(_1712, 9.9999999392252902907785028219223e-09));
    float _1721 = _1712 * float(frame.punctualLights[1].positionFalloff.w);
    float _1726 = fast::clamp(fma(-_1721, _1721, 1.0), 0.0, 1.0);
    float _1745 = fast::clamp(fma(dot(-_1717, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1860 = fast::normalize(_762 + _1717);
    float _1805 = fast::clamp(dot(_756, _1717), 0.0, 1.0);
    float3 _1898 = cross(_756, _1860);
    float _1901 = fast::clamp(dot(_756, _1860), 0.0, 1.0) * params.facet_alpha;
    float _1910 = params.facet_alpha / fma(_1901, _1901, dot(_1898, _1898));
    float _1956 = 1.0 - fast::clamp(dot(_1717, _1860), 0.0, 1.0);
    float _1959 = _1956 * _1956;
    float3 _1989 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_762, _756), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1089.xxx, _1089.yyy, float3(params.facet_f0)) * _1108, fast::min((((float3(params.facet_f0) + (_1337 * ((_1329 * _1329) * _1326))) * (((_1280 * _1280) * 0.3183098733425140380859375) * (0.5 / fma(_1175, _1303, _1050 * sqrt(fma(_1175 * _1175, _1299, _1293)))))) * _1108) * (frame.lightColor.xyz * _1175), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1337 * ((_1644 * _1644) * _1641))) * (((_1595 * _1595) * 0.3183098733425140380859375) * (0.5 / fma(_1490, _1303, _1050 * sqrt(fma(_1490 * _1490, _1299, _1293)))))) * _1108) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1411 * _1411) / fast::max(_1397, 9.9999997473787516355514526367188e-05)) * _1430) * _1430)) * _1490), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1337 * ((_1959 * _1959) * _1956))) * (((_1910 * _1910) * 0.3183098733425140380859375) * (0.5 / fma(_1805, _1303, _1050 * sqrt(fma(_1805 * _1805, _1299, _1293)))))) * _1108) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1726 * _1726) / fast::max(_1712, 9.9999997473787516355514526367188e-05)) * _1745) * _1745)) * _1805), float3(65504.0));
    out.fragColor = float4(_1989, 1.0);
    return out;
}

