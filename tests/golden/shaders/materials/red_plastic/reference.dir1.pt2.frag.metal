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
    float3 _774 = fast::normalize(in.v_normal);
    float3 _780 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _935 = _774.y;
    float _940 = _774.z;
    float _945 = _774.x;
    float _1063 = fast::max(dot(_774, _780), 9.9999997473787516355514526367188e-05);
    float4 _1102 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1063, params.facet_perceptualRoughness), level(0.0));
    float3 _1121 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1102.y) - 1.0));
    float3 _1246 = fast::normalize(_780 + frame.lightDirection.xyz);
    float _1191 = fast::clamp(dot(_774, frame.lightDirection.xyz), 0.0, 1.0);
    float _1284 = 4096.0 * params.facet_alpha;
    float4 _1308 = float4(cross(_774, _1246), params.facet_alpha * fast::clamp(dot(_774, _1246), 0.0, 1.0)) * 64.0;
    float _1290 = _1284 / dot(_1308, _1308);
    float _1319 = params.facet_alpha * params.facet_alpha;
    float _1325 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1329 = sqrt(fma(_1063 * _1063, _1325, _1319));
    float _1352 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1246), 0.0, 1.0);
    float _1355 = _1352 * _1352;
    float3 _1363 = float3(1.0) - float3(params.facet_f0);
    float3 _1222 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1377 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _935)) + (frame.sh[2].xyz * _940)) + (frame.sh[3].xyz * _945)) + (((((frame.sh[4].xyz * (_945 * _935)) + (frame.sh[5].xyz * (_935 * _940))) + (frame.sh[6].xyz * fma(3.0 * _940, _940, -1.0))) + (frame.sh[7].xyz * (_945 * _940))) + (frame.sh[8].xyz * fma(_945, _945, -(_935 * _935)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_780, _774), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1102.xxx, _1102.yyy, float3(params.facet_f0)) * _1121)) + fast::min(fma((float3(params.facet_f0) + (_1363 * ((_1355 * _1355) * _1352))) * (((_1290 * _1290) * 0.3183098733425140380859375) * (0.5 / fma(_1191, _1329, _1063 * sqrt(fma(_1191 * _1191, _1325, _1319))))), _1121, _1222) * (frame.lightColor.xyz * _1191), float3(65504.0));
    float3 _1412 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1415 = dot(_1412, _1412);
    float3 _1420 = _1412 * rsqrt(fast::max(_1415, 9.9999999392252902907785028219223e-09));
    float _1424 = _1415 * float(frame.punctualLights[0].positionFalloff.w);
    float _1429 = fast::clamp(fma(-_1424, _1424, 1.0), 0.0, 1.0);
    float _1448 = fast::clamp(fma(dot(-_1420, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1563 = fast::normalize(_780 + _1420);
    float _1508 = fast::clamp(dot(_774, _1420), 0.0, 1.0);
    float4 _1625 = float4(cross(_774, _1563), params.facet_alpha * fast::clamp(dot(_774, _1563), 0.0, 1.0)) * 64.0;
    float _1607 = _1284 / dot(_1625, _1625);
    float _1669 = 1.0 - fast::clamp(dot(_1420, _1563), 0.0, 1.0);
    float _1672 = _1669 * _1669;
    float3 _1729 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1732 = dot(_1729, _1729);
    float3 _1737 = _1729 * rsqrt(fast::max(_1732, 9.9999999392252902907785028219223e-09));
    float _1741 = _1732 * float(frame.punctualLights[1].positionFalloff.w);
    float _1746 = fast::clamp(fma(-_1741, _1741, 1.0), 0.0, 1.0);
    float _1765 = fast::clamp(fma(dot(-_1737, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1880 = fast::normalize(_780 + _1737);
    float _1825 = fast::clamp(dot(_774, _1737), 0.0, 1.0);
    float4 _1942 = float4(cross(_774, _1880), params.facet_alpha * fast::clamp(dot(_774, _1880), 0.0, 1.0)) * 64.0;
    float _1924 = _1284 / dot(_1942, _1942);
    float _1986 = 1.0 - fast::clamp(dot(_1737, _1880), 0.0, 1.0);
    float _1989 = _1986 * _1986;
    float3 _2011 = (_1377 + fast::min(fma((float3(params.facet_f0) + (_1363 * ((_1672 * _1672) * _1669))) * (((_1607 * _1607) * 0.3183098733425140380859375) * (0.5 / fma(_1508, _1329, _1063 * sqrt(fma(_1508 * _1508, _1325, _1319))))), _1121, _1222) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1429 * _1429) / fast::max(_1415, 9.9999997473787516355514526367188e-05)) * _1448) * _1448)) * _1508), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1363 * ((_1989 * _1989) * _1986))) * (((_1924 * _1924) * 0.3183098733425140380859375) * (0.5 / fma(_1825, _1329, _1063 * sqrt(fma(_1825 * _1825, _1325, _1319))))), _1121, _1222) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1746 * _1746) / fast::max(_1732, 9.9999997473787516355514526367188e-05)) * _1765) * _1765)) * _1825), float3(65504.0));
    out.fragColor = float4(_2011, 1.0);
    return out;
}

