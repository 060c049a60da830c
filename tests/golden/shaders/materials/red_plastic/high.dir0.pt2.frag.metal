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
    half _904 = _761.y;
    half _909 = _761.z;
    half _914 = _761.x;
    half3 _982 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _904)) + (half4(frame.sh[2]).xyz * _909)) + (half4(frame.sh[3]).xyz * _914)) + (((((half4(frame.sh[4]).xyz * (_914 * _904)) + (half4(frame.sh[5]).xyz * (_904 * _909))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _909, _909, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_914 * _909))) + (half4(frame.sh[8]).xyz * fma(_914, _914, half(-float(_904 * _904))))), half3(float3(0.0)));
    half _1032 = max(dot(_761, half3(_767)), half(9.9999997473787516355514526367188e-05));
    float4 _1071 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1032, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1090 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1071).y) - half(1.0)));
    float4 _1097 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_767), _761)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1142 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1145 = dot(_1142, _1142);
    float3 _1150 = _1142 * rsqrt(fast::max(_1145, 9.9999999392252902907785028219223e-09));
    float _1154 = _1145 * float(frame.punctualLights[0].positionFalloff.w);
    float _1159 = fast::clamp(fma(-_1154, _1154, 1.0), 0.0, 1.0);
    float _1178 = fast::clamp(fma(dot(-_1150, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1297 = fast::normalize(_767 + _1150);
    half _1241 = clamp(dot(_761, half3(_1150)), half(0.0), half(1.0));
    half3 _1337 = cross(_761, half3(_1297));
    half _1340 = clamp(dot(_761, half3(_1297)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1349 = half(params.facet_alpha) / fma(_1340, _1340, dot(_1337, _1337));
    half _1363 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1369 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1373 = sqrt(fma(_1032 * _1032, _1369, _1363));
    half _1397 = half(1.0) - clamp(dot(half3(_1150), half3(_1297)), half(0.0), half(1.0));
    half _1400 = _1397 * _1397;
    half3 _1408 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1272 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1458 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1461 = dot(_1458, _1458);
    float3 _1466 = _1458 * rsqrt(fast::max(_1461, 9.9999999392252902907785028219223e-09));
    float _1470 = _1461 * float(frame.punctualLights[1].positionFalloff.w);
    float _1475 = fast::clamp(fma(-_1470, _1470, 1.0), 0.0, 1.0);
    float _1494 = fast::clamp(fma(dot(-_1466, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1613 = fast::normalize(_767 + _1466);
    half _1557 = clamp(dot(_761, half3(_1466)), half(0.0), half(1.0));
    half3 _1653 = cross(_761, half3(_1613));
    half _1656 = clamp(dot(_761, half3(_1613)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1665 = half(params.facet_alpha) / fma(_1656, _1656, dot(_1653, _1653));
    half _1713 = half(1.0) - clamp(dot(half3(_1466), half3(_1613)), half(0.0), half(1.0));
    half _1716 = _1713 * _1713;
    half3 _1738 = (fma(half3(float3(params.facet_diffuseColor)), _982, half4(_1097).xyz * (mix(half4(_1071).xxx, half4(_1071).yyy, half3(float3(params.facet_f0))) * _1090)) + min(fma((half3(float3(params.facet_f0)) + (_1408 * ((_1400 * _1400) * _1397))) * min(min((_1349 * _1349) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1241, _1373, _1032 * sqrt(fma(_1241 * _1241, _1369, _1363))), half(65504.0)), half(65504.0)), _1090, _1272) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1159) * half(_1159)) / fast::max(_1145, 9.9999997473787516355514526367188e-05)) * half(_1178)) * half(_1178)), float3(65504.0))) * _1241), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1408 * ((_1716 * _1716) * _1713))) * min(min((_1665 * _1665) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1557, _1373, _1032 * sqrt(fma(_1557 * _1557, _1369, _1363))), half(65504.0)), half(65504.0)), _1090, _1272) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1475) * half(_1475)) / fast::max(_1461, 9.9999997473787516355514526367188e-05)) * half(_1494)) * half(_1494)), float3(65504.0))) * _1557), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1738, half(1.0)));
    return out;
}

