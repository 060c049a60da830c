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
    float3 _1243 = fast::normalize(_780 + frame.lightDirection.xyz);
    float _1188 = fast::clamp(dot(_774, frame.lightDirection.xyz), 0.0, 1.0);
    float _1282 = 4096.0 * params.facet_alpha;
    float3 _1301 = cross(_774, _1243) * 64.0;
    float _1304 = 64.0 * params.facet_alpha;
    float _1305 = fast::clamp(dot(_774, _1243), 0.0, 1.0) * _1304;
    float _1288 = _1282 / fma(_1305, _1305, dot(_1301, _1301));
    float _1320 = params.facet_alpha * params.facet_alpha;
    float _1326 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1330 = sqrt(fma(_1063 * _1063, _1326, _1320));
    float _1353 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1243), 0.0, 1.0);
    float _1356 = _1353 * _1353;
    float3 _1364 = float3(1.0) - float3(params.facet_f0);
    float3 _1219 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1378 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _935)) + (frame.sh[2].xyz * _940)) + (frame.sh[3].xyz * _945)) + (((((frame.sh[4].xyz * (_945 * _935)) + (frame.sh[5].xyz * (_935 * _940))) + (frame.sh[6].xyz * fma(3.0 * _940, _940, -1.0))) + (frame.sh[7].xyz * (_945 * _940))) + (frame.sh[8].xyz * fma(_945, _945, -(_935 * _935)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_780, _774), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1102.xxx, _1102.yyy, float3(params.facet_f0)) * _1121)) + fast::min(fma((float3(params.facet_f0) + (_1364 * ((_1356 * _1356) * _1353))) * (((_1288 * _1288) * 0.3183098733425140380859375) * (0.5 / fma(_1188, _1330, _1063 * sqrt(fma(_1188 * _1188, _1326, _1320))))), _1121, _1219) * (frame.lightColor.xyz * _1188), float3(65504.0));
    float3 _1413 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1416 = dot(_1413, _1413);
    float3 _1421 = _1413 * rsqrt(fast::max(_1416, 9.9999999392252902907785028219223e-09));
    float _1425 = _1416 * float(frame.punctualLights[0].positionFalloff.w);
    float _1430 = fast::clamp(fma(-_1425, _1425, 1.0), 0.0, 1.0);
    float _1449 = fast::clamp(fma(dot(-_1421, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1564 = fast::normalize(_780 + _1421);
    float _1509 = fast::clamp(dot(_774, _1421), 0.0, 1.0);
    float3 _1622 = cross(_774, _1564) * 64.0;
    float _1626 = fast::clamp(dot(_774, _1564), 0.0, 1.0) * _1304;
    float _1609 = _1282 / fma(_1626, _1626, dot(_1622, _1622));
    float _1674 = 1.0 - fast::clamp(dot(_1421, _1564), 0.0, 1.0);
    float _1677 = _1674 * _1674;
    float3 _1734 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1737 = dot(_1734, _1734);
    float3 _1742 = _1734 * rsqrt(fast::max(_1737, 9.9999999392252902907785028219223e-09));
    float _1746 = _1737 * float(frame.punctualLights[1].positionFalloff.w);
    float _1751 = fast::clamp(fma(-_1746, _1746, 1.0), 0.0, 1.0);
    float _1770 = fast::clamp(fma(dot(-_1742, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1885 = fast::normalize(_780 + _1742);
    float _1830 = fast::clamp(dot(_774, _1742), 0.0, 1.0);
    float3 _1943 = cross(_774, _1885) * 64.0;
    float _1947 = fast::clamp(dot(_774, _1885), 0.0, 1.0) * _1304;
    float _1930 = _1282 / fma(_1947, _1947, dot(_1943, _1943));
    float _1995 = 1.0 - fast::clamp(dot(_1742, _1885), 0.0, 1.0);
    float _1998 = _1995 * _1995;
    float3 _2020 = (_1378 + fast::min(fma((float3(params.facet_f0) + (_1364 * ((_1677 * _1677) * _1674))) * (((_1609 * _1609) * 0.3183098733425140380859375) * (0.5 / fma(_1509, _1330, _1063 * sqrt(fma(_1509 * _1509, _1326, _1320))))), _1121, _1219) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1430 * _1430) / fast::max(_1416, 9.9999997473787516355514526367188e-05)) * _1449) * _1449)) * _1509), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1364 * ((_1998 * _1998) * _1995))) * (((_1930 * _1930) * 0.3183098733425140380859375) * (0.5 / fma(_1830, _1330, _1063 * sqrt(fma(_1830 * _1830, _1326, _1320))))), _1121, _1219) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1751 * _1751) / fast::max(_1737, 9.9999997473787516355514526367188e-05)) * _1770) * _1770)) * _1830), float3(65504.0));
    out.fragColor = float4(_2020, 1.0);
    return out;
}

