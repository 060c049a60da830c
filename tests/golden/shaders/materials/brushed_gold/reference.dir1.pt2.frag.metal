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
    float3 _762 = fast::normalize(in.v_normal);
    float3 _768 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1056 = fast::max(dot(_762, _768), 9.9999997473787516355514526367188e-05);
    float4 _1095 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1056, params.facet_perceptualRoughness), level(0.0));
    float3 _1114 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1095.y) - 1.0));
    float3 _1241 = fast::normalize(_768 + frame.lightDirection.xyz);
    float _1186 = fast::clamp(dot(_762, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1279 = cross(_762, _1241);
    float _1282 = fast::clamp(dot(_762, _1241), 0.0, 1.0) * params.facet_alpha;
    float _1291 = params.facet_alpha / fma(_1282, _1282, dot(_1279, _1279));
    float _1304 = params.facet_alpha * params.facet_alpha;
    float _1310 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1314 = sqrt(fma(_1056 * _1056, _1310, _1304));
    float _1337 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1241), 0.0, 1.0);
    float _1340 = _1337 * _1337;
    float3 _1348 = float3(1.0) - float3(params.facet_f0);
    float3 _1405 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1408 = dot(_1405, _1405);
    float3 _1413 = _1405 * rsqrt(fast::max(_1408, 9.9999999392252902907785028219223e-09));
    float _1417 = _1408 * float(frame.punctualLights[0].positionFalloff.w);
    float _1422 = fast::clamp(fma(-_1417, _1417, 1.0), 0.0, 1.0);
    float _1441 = fast::clamp(fma(dot(-_1413, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1556 = fast::normalize(_768 + _1413);
    float _1501 = fast::clamp(dot(_762, _1413), 0.0, 1.0);
    float3 _1594 = cross(_762, _1556);
    float _1597 = fast::clamp(dot(_762, _1556), 0.0, 1.0) * params.facet_alpha;
    float _1606 = params.facet_alpha / fma(_1597, _1597, dot(_1594, _1594));
    float _1652 = 1.0 - fast::clamp(dot(_1413, _1556), 0.0, 1.0);
    float _1655 = _1652 * _1652;
    float3 _1720 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1723 = dot(_1720, _1720);
    float3 _1728 = _1720 * rsqrt(fast::max(_1723, 9.9999999392252902907785028219223e-09));
    float _1732 = _1723 * float(frame.punctualLights[1].positionFalloff.w);
    float _1737 = fast::clamp(fma(-_1732, _1732, 1.0), 0.0, 1.0);
    float _1756 = fast::clamp(fma(dot(-_1728, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1871 = fast::normalize(_768 + _1728);
    float _1816 = fast::clamp(dot(_762, _1728), 0.0, 1.0);
    float3 _1909 = cross(_762, _1871);
    float _1912 = fast::clamp(dot(_762, _1871), 0.0, 1.0) * params.facet_alpha;
    float _1921 = params.facet_alpha / fma(_1912, _1912, dot(_1909, _1909));
    float _1967 = 1.0 - fast::clamp(dot(_1728, _1871), 0.0, 1.0);
    float _1970 = _1967 * _1967;
    float3 _2000 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_768, _762), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1095.xxx, _1095.yyy, float3(params.facet_f0)) * _1114, fast::min((((float3(params.facet_f0) + (_1348 * ((_1340 * _1340) * _1337))) * (((_1291 * _1291) * 0.3183098733425140380859375) * (0.5 / fma(_1186, _1314, _1056 * sqrt(fma(_1186 * _1186, _1310, _1304)))))) * _1114) * (frame.lightColor.xyz * _1186), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1348 * ((_1655 * _1655) * _1652))) * (((_1606 * _1606) * 0.3183098733425140380859375) * (0.5 / fma(_1501, _1314, _1056 * sqrt(fma(_1501 * _1501, _1310, _1304)))))) * _1114) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1422 * _1422) / fast::max(_1408, 9.9999997473787516355514526367188e-05)) * _1441) * _1441)) * _1501), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1348 * ((_1970 * _1970) * _1967))) * (((_1921 * _1921) * 0.3183098733425140380859375) * (0.5 / fma(_1816, _1314, _1056 * sqrt(fma(_1816 * _1816, _1310, _1304)))))) * _1114) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1737 * _1737) / fast::max(_1723, 9.9999997473787516355514526367188e-05)) * _1756) * _1756)) * _1816), float3(65504.0));
    out.fragColor = float4(_2000, 1.0);
    return out;
}

