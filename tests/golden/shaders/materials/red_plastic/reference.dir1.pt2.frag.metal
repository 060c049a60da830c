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
    float3 _752 = fast::normalize(in.v_normal);
    float3 _758 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _916 = _752.y;
    float _921 = _752.z;
    float _926 = _752.x;
    float _1044 = fast::max(dot(_752, _758), 9.9999997473787516355514526367188e-05);
    float4 _1083 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1044, params.facet_perceptualRoughness), level(0.0));
    float3 _1102 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1083.y) - 1.0));
    float3 _1224 = fast::normalize(_758 + frame.lightDirection.xyz);
    float _1169 = fast::clamp(dot(_752, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1262 = cross(_752, _1224);
    float _1265 = fast::clamp(dot(_752, _1224), 0.0, 1.0) * params.facet_alpha;
    float _1274 = params.facet_alpha / fma(_1265, _1265, dot(_1262, _1262));
    float _1287 = params.facet_alpha * params.facet_alpha;
    float _1293 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1297 = sqrt(fma(_1044 * _1044, _1293, _1287));
    float _1320 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1224), 0.0, 1.0);
    float _1323 = _1320 * _1320;
    float3 _1331 = float3(1.0) - float3(params.facet_f0);
    float3 _1200 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1345 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _916)) + (frame.sh[2].xyz * _921)) + (frame.sh[3].xyz * _926)) + (((((frame.sh[4].xyz * (_926 * _916)) + (frame.sh[5].xyz * (_916 * _921))) + (frame.sh[6].xyz * fma(3.0 * _921, _921, -1.0))) + (frame.sh[7].xyz * (_926 * _921))) + (frame.sh[8].xyz * fma(_926, _926, -(_916 * _916)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_758, _752), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1083.xxx, _1083.yyy, float3(params.facet_f0)) * _1102)) + fast::min(fma((float3(params.facet_f0) + (_1331 * ((_1323 * _1323) * _1320))) * (((_1274 * _1274) * 0.3183098733425140380859375) * (0.5 / fma(_1169, _1297, _1044 * sqrt(fma(_1169 * _1169, _1293, _1287))))), _1102, _1200) * (frame.lightColor.xyz * _1169), float3(65504.0));
    float3 _1380 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1383 = dot(_1380, _1380);
    float3 _1388 = _1380 * rsqrt(fast::max(_1383, 9.9999999392252902907785028219223e-09));
    float _1392 = _1383 * float(frame.punctualLights[0].positionFalloff.w);
    float _1397 = fast::clamp(fma(-_1392, _1392, 1.0), 0.0, 1.0);
    float _1416 = fast::clamp(fma(dot(-_1388, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1531 = fast::normalize(_758 + _1388);
    float _1476 = fast::clamp(dot(_752, _1388), 0.0, 1.0);
    float3 _1569 = cross(_752, _1531);
    float _1572 = fast::clamp(dot(_752, _1531), 0.0, 1.0) * params.facet_alpha;
    float _1581 = params.facet_alpha / fma(_1572, _1572, dot(_1569, _1569));
    float _1627 = 1.0 - fast::clamp(dot(_1388, _1531), 0.0, 1.0);
    float _1630 = _1627 * _1627;
    float3 _1687 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1690 = dot(_1687, _1687);
    float3 _1695 = _1687 * rsqrt(fast::max(_1690, 9.9999999392252902907785028219223e-09));
    float _1699 = _1690 * float(frame.punctualLights[1].positionFalloff.w);
    float _1704 = fast::clamp(fma(-_1699, _1699, 1.0), 0.0, 1.0);
    float _1723 = fast::clamp(fma(dot(-_1695, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1838 = fast::normalize(_758 + _1695);
    float _1783 = fast::clamp(dot(_752, _1695), 0.0, 1.0);
    float3 _1876 = cross(_752, _1838);
    float _1879 = fast::clamp(dot(_752, _1838), 0.0, 1.0) * params.facet_alpha;
    float _1888 = params.facet_alpha / fma(_1879, _1879, dot(_1876, _1876));
    float _1934 = 1.0 - fast::clamp(dot(_1695, _1838), 0.0, 1.0);
    float _1937 = _1934 * _1934;
    float3 _1959 = (_1345 + fast::min(fma((float3(params.facet_f0) + (_1331 * ((_1630 * _1630) * _1627))) * (((_1581 * _1581) * 0.3183098733425140380859375) * (0.5 / fma(_1476, _1297, _1044 * sqrt(fma(_1476 * _1476, _1293, _1287))))), _1102, _1200) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1397 * _1397) / fast::max(_1383, 9.9999997473787516355514526367188e-05)) * _1416) * _1416)) * _1476), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1331 * ((_1937 * _1937) * _1934))) * (((_1888 * _1888) * 0.3183098733425140380859375) * (0.5 / fma(_1783, _1297, _1044 * sqrt(fma(_1783 * _1783, _1293, _1287))))), _1102, _1200) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1704 * _1704) / fast::max(_1690, 9.9999997473787516355514526367188e-05)) * _1723) * _1723)) * _1783), float3(65504.0));
    out.fragColor = float4(_1959, 1.0);
    return out;
}

