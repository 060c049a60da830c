#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float _917 = _756.y;
    float _922 = _756.z;
    float _927 = _756.x;
    float _1045 = fast::max(dot(_756, _762), 9.9999997473787516355514526367188e-05);
    float4 _1084 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1045, params.facet_perceptualRoughness), level(0.0));
    float3 _1103 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1084.y) - 1.0));
    float3 _1228 = fast::normalize(_762 + frame.lightDirection.xyz);
    float _1173 = fast::clamp(dot(_756, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1266 = cross(_756, _1228);
    float _1269 = fast::clamp(dot(_756, _1228), 0.0, 1.0) * params.facet_alpha;
    float _1278 = params.facet_alpha / fma(_1269, _1269, dot(_1266, _1266));
    float _1291 = params.facet_alpha * params.facet_alpha;
    float _1297 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1301 = sqrt(fma(_1045 * _1045, _1297, _1291));
    float _1324 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1228), 0.0, 1.0);
    float _1327 = _1324 * _1324;
    float3 _1335 = float3(1.0) - float3(params.facet_f0);
    float3 _1204 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1349 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _917)) + (frame.sh[2].xyz * _922)) + (frame.sh[3].xyz * _927)) + (((((frame.sh[4].xyz * (_927 * _917)) + (frame.sh[5].xyz * (_917 * _922))) + (frame.sh[6].xyz * fma(3.0 * _922, _922, -1.0))) + (frame.sh[7].xyz * (_927 * _922))) + (frame.sh[8].xyz * fma(_927, _927, -(_917 * _917)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_762, _756), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1084.xxx, _1084.yyy, float3(params.facet_f0)) * _1103)) + fast::min(fma((float3(params.facet_f0) + (_1335 * ((_1327 * _1327) * _1324))) * (((_1278 * _1278) * 0.3183098733425140380859375) * (0.5 / fma(_1173, _1301, _1045 * sqrt(fma(_1173 * _1173, _1297, _1291))))), _1103, _1204) * (frame.lightColor.xyz * _1173), float3(65504.0));
    float3 _1384 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1387 = dot(_1384, _1384);
    float3 _1392 = _1384 * rsqrt(fast::max(_1387, 9.9999999392252902907785028219223e-09));
    float _1396 = _1387 * float(frame.punctualLights[0].positionFalloff.w);
    float _1401 = fast::clamp(fma(-_1396, _1396, 1.0), 0.0, 1.0);
    float _1420 = fast::clamp(fma(dot(-_1392, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1535 = fast::normalize(_762 + _1392);
    float _1480 = fast::clamp(dot(_756, _1392), 0.0, 1.0);
    float3 _1573 = cross(_756, _1535);
    float _1576 = fast::clamp(dot(_756, _1535), 0.0, 1.0) * params.facet_alpha;
    float _1585 = params.facet_alpha / fma(_1576, _1576, dot(_1573, _1573));
    float _1631 = 1.0 - fast::clamp(dot(_1392, _1535), 0.0, 1.0);
    float _1634 = _1631 * _1631;
    float3 _1691 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1694 = dot(_1691, _1691);
    float3 _1699 = _1691 * rsqrt(fast::max(_1694, 9.9999999392252902907785028219223e-09));
    float _1703 = _1694 * float(frame.punctualLights[1].positionFalloff.w);
    float _1708 = fast::clamp(fma(-_1703, _1703, 1.0), 0.0, 1.0);
    float _1727 = fast::clamp(fma(dot(-_1699, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1842 = fast::normalize(_762 + _1699);
    float _1787 = fast::clamp(dot(_756, _1699), 0.0, 1.0);
    float3 _1880 = cross(_756, _1842);
    float _1883 = fast::clamp(dot(_756, _1842), 0.0, 1.0) * params.facet_alpha;
    float _1892 = params.facet_alpha / fma(_1883, _1883, dot(_1880, _1880));
    float _1938 = 1.0 - fast::clamp(dot(_1699, _1842), 0.0, 1.0);
    float _1941 = _1938 * _1938;
    float3 _1963 = (_1349 + fast::min(fma((float3(params.facet_f0) + (_1335 * ((_1634 * _1634) * _1631))) * (((_1585 * _1585) * 0.3183098733425140380859375) * (0.5 / fma(_1480, _1301, _1045 * sqrt(fma(_1480 * _1480, _1297, _1291))))), _1103, _1204) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1401 * _1401) / fast::max(_1387, 9.9999997473787516355514526367188e-05)) * _1420) * _1420)) * _1480), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1335 * ((_1941 * _1941) * _1938))) * (((_1892 * _1892) * 0.3183098733425140380859375) * (0.5 / fma(_1787, _1301, _1045 * sqrt(fma(_1787 * _1787, _1297, _1291))))), _1103, _1204) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1708 * _1708) / fast::max(_1694, 9.9999997473787516355514526367188e-05)) * _1727) * _1727)) * _1787), float3(65504.0));
    out.fragColor = float4(_1963, 1.0);
    return out;
}

