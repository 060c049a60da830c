#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    float3 _1001 = fast::normalize(in.v_normal);
    float3 _1007 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1153 = _1001.y;
    float _1158 = _1001.z;
    float _1163 = _1001.x;
    float _1281 = fast::max(dot(_1001, _1007), 9.9999997473787516355514526367188e-05);
    float3 _1285 = reflect(-_1007, _1001);
    float4 _1320 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1281, params.facet_perceptualRoughness), level(0.0));
    float3 _1339 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1320.y) - 1.0));
    float _1419 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1379 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1281, _1419), level(0.0));
    float3 _1426 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1392 = _1379.z;
    float _1394 = fma(-fast::max(_1426.x, fast::max(_1426.y, _1426.z)), _1392, 1.0);
    float _1396 = _1379.w;
    float3 _1412 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1153)) + (frame.sh[2].xyz * _1158)) + (frame.sh[3].xyz * _1163)) + (((((frame.sh[4].xyz * (_1163 * _1153)) + (frame.sh[5].xyz * (_1153 * _1158))) + (frame.sh[6].xyz * fma(3.0 * _1158, _1158, -1.0))) + (frame.sh[7].xyz * (_1163 * _1158))) + (frame.sh[8].xyz * fma(_1163, _1163, -(_1153 * _1153)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1285, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1320.xxx, _1320.yyy, float3(params.facet_f0)) * _1339)) * _1394;
    float3 _1469 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1472 = dot(_1469, _1469);
    float3 _1477 = _1469 * rsqrt(fast::max(_1472, 9.9999999392252902907785028219223e-09));
    float _1481 = _1472 * float(frame.punctualLights[0].positionFalloff.w);
    float _1486 = fast::clamp(fma(-_1481, _1481, 1.0), 0.0, 1.0);
    float _1505 = fast::clamp(fma(dot(-_1477, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1514 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1486 * _1486) / fast::max(_1472, 9.9999997473787516355514526367188e-05)) * _1505) * _1505);
    float3 _1652 = fast::normalize(_1007 + _1477);
    float _1594 = fast::clamp(dot(_1001, _1477), 0.0, 1.0);
    float _1598 = fast::clamp(dot(_1001, _1652), 0.0, 1.0);
    float3 _1690 = cross(_1001, _1652);
    float _1693 = _1598 * params.facet_alpha;
    float _1702 = params.facet_alpha / fma(_1693, _1693, dot(_1690, _1690));
    float _1715 = params.facet_alpha * params.facet_alpha;
    float _1721 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1725 = sqrt(fma(_1281 * _1281, _1721, _1715));
    float _1748 = 1.0 - fast::clamp(dot(_1477, _1652), 0.0, 1.0);
    float _1751 = _1748 * _1748;
    float3 _1759 = float3(1.0) - float3(params.facet_f0);
    float3 _1628 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float _1829 = _1419 * _1419;
    float _1849 = 8192.0 * fma(-_1594, _1281, _1594 + _1281);
    float _1853 = 1.0 / (_1829 * _1849);
    float _1860 = 2048.0 * _1829;
    float3 _1929 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1932 = dot(_1929, _1929);
    float3 _1937 = _1929 * rsqrt(fast::max(_1932, 9.9999999392252902907785028219223e-09));
    float _1941 = _1932 * float(frame.punctualLights[1].positionFalloff.w);
    float _1946 = fast::clamp(fma(-_1941, _1941, 1.0), 0.0, 1.0);
    float _1965 = fast::clamp(fma(dot(-_1937, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1974 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1946 * _1946) / fast::max(_1932, 9.9999997473787516355514526367188e-05)) * _1965) * _1965);
    float3 _2112 = fast::normalize(_1007 + _1937);
    float _2054 = fast::clamp(dot(_1001, _1937), 0.0, 1.0);
    float _2058 = fast::clamp(dot(_1001, _2112), 0.0, 1.0);
    float3 _2150 = cross(_1001, _2112);
    float _2153 = _2058 * params.facet_alpha;
    float _2162 = params.facet_alpha / fma(_2153, _2153, dot(_2150, _2150));
    float _2208 = 1.0 - fast::clamp(dot(_1937, _2112), 0.0, 1.0);
    float _2211 = _2208 * _2208;
    float _2309 = 8192.0 * fma(-_2054, _1281, _2054 + _1281);
    float _2313 = 1.0 / (_1829 * _2309);
    float3 _2354 = (fma(facet_environment.sample(facet_environmentSmplr, _1285, level(_1419 * 4.0)).xyz, _1426 * _1392, _1412) + (fast::min(fma((float3(params.facet_f0) + (_1759 * ((_1751 * _1751) * _1748))) * (((_1702 * _1702) * 0.3183098733425140380859375) * (0.5 / fma(_1594, _1725, _1281 * sqrt(fma(_1594 * _1594, _1721, _1715))))), _1339, _1628) * ((_1514 * _1594) * _1394), float3(65504.0)) + fast::min((_1426 * ((((fma(_1853, _1849, 2.0) * pow(fast::max(fma(-_1598, _1598, 1.0), 0.0), 0.5 * (_1853 * _1849))) * 0.15915493667125701904296875) * (_1594 * (_1853 * _1860))) * _1396)) * _1514, float3(65504.0)))) + (fast::min(fma((float3(params.facet_f0) + (_1759 * ((_2211 * _2211) * _2208))) * (((_2162 * _2162) * 0.3183098733425140380859375) * (0.5 / fma(_2054, _1725, _1281 * sqrt(fma(_2054 * _2054, _1721, _1715))))), _1339, _1628) * ((_1974 * _2054) * _1394), float3(65504.0)) + fast::min((_1426 * ((((fma(_2313, _2309, 2.0) * pow(fast::max(fma(-_2058, _2058, 1.0), 0.0), 0.5 * (_2313 * _2309))) * 0.15915493667125701904296875) * (_2054 * (_2313 * _1860))) * _1396)) * _1974, float3(65504.0)));
    out.fragColor = float4(_2354, 1.0);
    return out;
}

