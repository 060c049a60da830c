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
    float _913 = _752.y;
    float _918 = _752.z;
    float _923 = _752.x;
    float _1041 = fast::max(dot(_752, _758), 9.9999997473787516355514526367188e-05);
    float4 _1080 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1041, params.facet_perceptualRoughness), level(0.0));
    float3 _1099 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1080.y) - 1.0));
    float3 _1221 = fast::normalize(_758 + frame.lightDirection.xyz);
    float _1166 = fast::clamp(dot(_752, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1259 = cross(_752, _1221);
    float _1262 = fast::clamp(dot(_752, _1221), 0.0, 1.0) * params.facet_alpha;
    float _1271 = params.facet_alpha / fma(_1262, _1262, dot(_1259, _1259));
    float _1284 = params.facet_alpha * params.facet_alpha;
    float _1290 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1294 = sqrt(fma(_1041 * _1041, _1290, _1284));
    float _1317 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1221), 0.0, 1.0);
    float _1320 = _1317 * _1317;
    float3 _1328 = float3(1.0) - float3(params.facet_f0);
    float3 _1197 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1342 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _913)) + (frame.sh[2].xyz * _918)) + (frame.sh[3].xyz * _923)) + (((((frame.sh[4].xyz * (_923 * _913)) + (frame.sh[5].xyz * (_913 * _918))) + (frame.sh[6].xyz * fma(3.0 * _918, _918, -1.0))) + (frame.sh[7].xyz * (_923 * _918))) + (frame.sh[8].xyz * fma(_923, _923, -(_913 * _913)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_758, _752), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1080.xxx, _1080.yyy, float3(params.facet_f0)) * _1099)) + fast::min(fma((float3(params.facet_f0) + (_1328 * ((_1320 * _1320) * _1317))) * (((_1271 * _1271) * 0.3183098733425140380859375) * (0.5 / fma(_1166, _1294, _1041 * sqrt(fma(_1166 * _1166, _1290, _1284))))), _1099, _1197) * (frame.lightColor.xyz * _1166), float3(65504.0));
    float3 _1377 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1380 = dot(_1377, _1377);
    float3 _1385 = _1377 * rsqrt(fast::max(_1380, 9.9999999392252902907785028219223e-09));
    float _1389 = _1380 * float(frame.punctualLights[0].positionFalloff.w);
    float _1394 = fast::clamp(fma(-_1389, _1389, 1.0), 0.0, 1.0);
    float _1413 = fast::clamp(fma(dot(-_1385, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1528 = fast::normalize(_758 + _1385);
    float _1473 = fast::clamp(dot(_752, _1385), 0.0, 1.0);
    float3 _1566 = cross(_752, _1528);
    float _1569 = fast::clamp(dot(_752, _1528), 0.0, 1.0) * params.facet_alpha;
    float _1578 = params.facet_alpha / fma(_1569, _1569, dot(_1566, _1566));
    float _1624 = 1.0 - fast::clamp(dot(_1385, _1528), 0.0, 1.0);
    float _1627 = _1624 * _1624;
    float3 _1684 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1687 = dot(_1684, _1684);
    float3 _1692 = _1684 * rsqrt(fast::max(_1687, 9.9999999392252902907785028219223e-09));
    float _1696 = _1687 * float(frame.punctualLights[1].positionFalloff.w);
    float _1701 = fast::clamp(fma(-_1696, _1696, 1.0), 0.0, 1.0);
    float _1720 = fast::clamp(fma(dot(-_1692, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1835 = fast::normalize(_758 + _1692);
    float _1780 = fast::clamp(dot(_752, _1692), 0.0, 1.0);
    float3 _1873 = cross(_752, _1835);
    float _1876 = fast::clamp(dot(_752, _1835), 0.0, 1.0) * params.facet_alpha;
    float _1885 = params.facet_alpha / fma(_1876, _1876, dot(_1873, _1873));
    float _1931 = 1.0 - fast::clamp(dot(_1692, _1835), 0.0, 1.0);
    float _1934 = _1931 * _1931;
    float3 _1956 = (_1342 + fast::min(fma((float3(params.facet_f0) + (_1328 * ((_1627 * _1627) * _1624))) * (((_1578 * _1578) * 0.3183098733425140380859375) * (0.5 / fma(_1473, _1294, _1041 * sqrt(fma(_1473 * _1473, _1290, _1284))))), _1099, _1197) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1394 * _1394) / fast::max(_1380, 9.9999997473787516355514526367188e-05)) * _1413) * _1413)) * _1473), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1328 * ((_1934 * _1934) * _1931))) * (((_1885 * _1885) * 0.3183098733425140380859375) * (0.5 / fma(_1780, _1294, _1041 * sqrt(fma(_1780 * _1780, _1290, _1284))))), _1099, _1197) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1701 * _1701) / fast::max(_1687, 9.9999997473787516355514526367188e-05)) * _1720) * _1720)) * _1780), float3(65504.0));
    out.fragColor = float4(_1956, 1.0);
    return out;
}

