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
    half3 _765 = normalize(half3(in.v_normal));
    float3 _771 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _905 = _765.y;
    half _910 = _765.z;
    half _915 = _765.x;
    half3 _983 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _905)) + (half4(frame.sh[2]).xyz * _910)) + (half4(frame.sh[3]).xyz * _915)) + (((((half4(frame.sh[4]).xyz * (_915 * _905)) + (half4(frame.sh[5]).xyz * (_905 * _910))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _910, _910, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_915 * _910))) + (half4(frame.sh[8]).xyz * fma(_915, _915, half(-float(_905 * _905))))), half3(float3(0.0)));
    half _1033 = max(dot(_765, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1072 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1033, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1091 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1072).y) - half(1.0)));
    float4 _1101 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _765)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1146 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1149 = dot(_1146, _1146);
    float3 _1154 = _1146 * rsqrt(fast::max(_1149, 9.9999999392252902907785028219223e-09));
    float _1158 = _1149 * float(frame.punctualLights[0].positionFalloff.w);
    float _1163 = fast::clamp(fma(-_1158, _1158, 1.0), 0.0, 1.0);
    float _1182 = fast::clamp(fma(dot(-_1154, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1301 = fast::normalize(_771 + _1154);
    half _1245 = clamp(dot(_765, half3(_1154)), half(0.0), half(1.0));
    half3 _1341 = cross(_765, half3(_1301));
    half _1344 = clamp(dot(_765, half3(_1301)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1353 = half(params.facet_alpha) / fma(_1344, _1344, dot(_1341, _1341));
    half _1367 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1373 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1377 = sqrt(fma(_1033 * _1033, _1373, _1367));
    half _1401 = half(1.0) - clamp(dot(half3(_1154), half3(_1301)), half(0.0), half(1.0));
    half _1404 = _1401 * _1401;
    half3 _1412 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1276 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1462 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1465 = dot(_1462, _1462);
    float3 _1470 = _1462 * rsqrt(fast::max(_1465, 9.9999999392252902907785028219223e-09));
    float _1474 = _1465 * float(frame.punctualLights[1].positionFalloff.w);
    float _1479 = fast::clamp(fma(-_1474, _1474, 1.0), 0.0, 1.0);
    float _1498 = fast::clamp(fma(dot(-_1470, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1617 = fast::normalize(_771 + _1470);
    half _1561 = clamp(dot(_765, half3(_1470)), half(0.0), half(1.0));
    half3 _1657 = cross(_765, half3(_1617));
    half _1660 = clamp(dot(_765, half3(_1617)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1669 = half(params.facet_alpha) / fma(_1660, _1660, dot(_1657, _1657));
    half _1717 = half(1.0) - clamp(dot(half3(_1470), half3(_1617)), half(0.0), half(1.0));
    half _1720 = _1717 * _1717;
    half3 _1742 = (fma(half3(float3(params.facet_diffuseColor)), _983, half4(_1101).xyz * (mix(half4(_1072).xxx, half4(_1072).yyy, half3(float3(params.facet_f0))) * _1091)) + min(fma((half3(float3(params.facet_f0)) + (_1412 * ((_1404 * _1404) * _1401))) * min(min((_1353 * _1353) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1245, _1377, _1033 * sqrt(fma(_1245 * _1245, _1373, _1367))), half(65504.0)), half(65504.0)), _1091, _1276) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1163) * half(_1163)) / fast::max(_1149, 9.9999997473787516355514526367188e-05)) * half(_1182)) * half(_1182)), float3(65504.0))) * _1245), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1412 * ((_1720 * _1720) * _1717))) * min(min((_1669 * _1669) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1561, _1377, _1033 * sqrt(fma(_1561 * _1561, _1373, _1367))), half(65504.0)), half(65504.0)), _1091, _1276) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1479) * half(_1479)) / fast::max(_1465, 9.9999997473787516355514526367188e-05)) * half(_1498)) * half(_1498)), float3(65504.0))) * _1561), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1742, half(1.0)));
    return out;
}

