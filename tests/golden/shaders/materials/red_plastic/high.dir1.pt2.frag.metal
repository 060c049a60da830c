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
    half3 _761 = normalize(half3(in.v_normal));
    float3 _767 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _922 = _761.y;
    half _927 = _761.z;
    half _932 = _761.x;
    half3 _1000 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _922)) + (half4(frame.sh[2]).xyz * _927)) + (half4(frame.sh[3]).xyz * _932)) + (((((half4(frame.sh[4]).xyz * (_932 * _922)) + (half4(frame.sh[5]).xyz * (_922 * _927))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _927, _927, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_932 * _927))) + (half4(frame.sh[8]).xyz * fma(_932, _932, half(-float(_922 * _922))))), half3(float3(0.0)));
    half _1050 = max(dot(_761, half3(_767)), half(9.9999997473787516355514526367188e-05));
    float4 _1089 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1050, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1108 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1089).y) - half(1.0)));
    float4 _1115 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_767), _761)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1231 = fast::normalize(_767 + frame.lightDirection.xyz);
    half _1175 = clamp(dot(_761, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1271 = cross(_761, half3(_1231));
    half _1274 = clamp(dot(_761, half3(_1231)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1283 = half(params.facet_alpha) / fma(_1274, _1274, dot(_1271, _1271));
    half _1297 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1303 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1307 = sqrt(fma(_1050 * _1050, _1303, _1297));
    half _1331 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1231)), half(0.0), half(1.0));
    half _1334 = _1331 * _1331;
    half3 _1342 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1206 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1392 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1395 = dot(_1392, _1392);
    float3 _1400 = _1392 * rsqrt(fast::max(_1395, 9.9999999392252902907785028219223e-09));
    float _1404 = _1395 * float(frame.punctualLights[0].positionFalloff.w);
    float _1409 = fast::clamp(fma(-_1404, _1404, 1.0), 0.0, 1.0);
    float _1428 = fast::clamp(fma(dot(-_1400, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1547 = fast::normalize(_767 + _1400);
    half _1491 = clamp(dot(_761, half3(_1400)), half(0.0), half(1.0));
    half3 _1587 = cross(_761, half3(_1547));
    half _1590 = clamp(dot(_761, half3(_1547)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1599 = half(params.facet_alpha) / fma(_1590, _1590, dot(_1587, _1587));
    half _1647 = half(1.0) - clamp(dot(half3(_1400), half3(_1547)), half(0.0), half(1.0));
    half _1650 = _1647 * _1647;
    half3 _1672 = (fma(half3(float3(params.facet_diffuseColor)), _1000, half4(_1115).xyz * (mix(half4(_1089).xxx, half4(_1089).yyy, half3(float3(params.facet_f0))) * _1108)) + min(fma((half3(float3(params.facet_f0)) + (_1342 * ((_1334 * _1334) * _1331))) * min(min((_1283 * _1283) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1175, _1307, _1050 * sqrt(fma(_1175 * _1175, _1303, _1297))), half(65504.0)), half(65504.0)), _1108, _1206) * (half4(frame.lightColor).xyz * _1175), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1342 * ((_1650 * _1650) * _1647))) * min(min((_1599 * _1599) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1491, _1307, _1050 * sqrt(fma(_1491 * _1491, _1303, _1297))), half(65504.0)), half(65504.0)), _1108, _1206) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1409) * half(_1409)) / fast::max(_1395, 9.9999997473787516355514526367188e-05)) * half(_1428)) * half(_1428)), float3(65504.0))) * _1491), half3(float3(65504.0)));
    float3 _1708 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1711 = dot(_1708, _1708);
    float3 _1716 = _1708 * rsqrt(fast::max(_1711, 9.9999999392252902907785028219223e-09));
    float _1720 = _1711 * float(frame.punctualLights[1].positionFalloff.w);
    float _1725 = fast::clamp(fma(-_1720, _1720, 1.0), 0.0, 1.0);
    float _1744 = fast::clamp(fma(dot(-_1716, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1863 = fast::normalize(_767 + _1716);
    half _1807 = clamp(dot(_761, half3(_1716)), half(0.0), half(1.0));
    half3 _1903 = cross(_761, half3(_1863));
    half _1906 = clamp(dot(_761, half3(_1863)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1915 = half(params.facet_alpha) / fma(_1906, _1906, dot(_1903, _1903));
    half _1963 = half(1.0) - clamp(dot(half3(_1716), half3(_1863)), half(0.0), half(1.0));
    half _1966 = _1963 * _1963;
    half3 _1988 = _1672 + min(fma((half3(float3(params.facet_f0)) + (_1342 * ((_1966 * _1966) * _1963))) * min(min((_1915 * _1915) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1807, _1307, _1050 * sqrt(fma(_1807 * _1807, _1303, _1297))), half(65504.0)), half(65504.0)), _1108, _1206) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1725) * half(_1725)) / fast::max(_1711, 9.9999997473787516355514526367188e-05)) * half(_1744)) * half(_1744)), float3(65504.0))) * _1807), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1988, half(1.0)));
    return out;
}

