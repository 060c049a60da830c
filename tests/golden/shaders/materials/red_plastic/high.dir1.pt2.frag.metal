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
    half3 _767 = normalize(half3(in.v_normal));
    float3 _773 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _928 = _767.y;
    half _933 = _767.z;
    half _938 = _767.x;
    half3 _1006 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _928)) + (half4(frame.sh[2]).xyz * _933)) + (half4(frame.sh[3]).xyz * _938)) + (((((half4(frame.sh[4]).xyz * (_938 * _928)) + (half4(frame.sh[5]).xyz * (_928 * _933))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _933, _933, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_938 * _933))) + (half4(frame.sh[8]).xyz * fma(_938, _938, half(-float(_928 * _928))))), half3(float3(0.0)));
    half _1056 = max(dot(_767, half3(_773)), half(9.9999997473787516355514526367188e-05));
    float4 _1095 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1056, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1114 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1095).y) - half(1.0)));
    float4 _1126 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_773), _767)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1242 = fast::normalize(_773 + frame.lightDirection.xyz);
    half _1186 = clamp(dot(_767, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1282 = cross(_767, half3(_1242));
    half _1285 = clamp(dot(_767, half3(_1242)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1294 = half(params.facet_alpha) / fma(_1285, _1285, dot(_1282, _1282));
    half _1308 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1314 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1318 = sqrt(fma(_1056 * _1056, _1314, _1308));
    half _1342 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1242)), half(0.0), half(1.0));
    half _1345 = _1342 * _1342;
    half3 _1353 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1217 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1403 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1406 = dot(_1403, _1403);
    float3 _1411 = _1403 * rsqrt(fast::max(_1406, 9.9999999392252902907785028219223e-09));
    float _1415 = _1406 * float(frame.punctualLights[0].positionFalloff.w);
    float _1420 = fast::clamp(fma(-_1415, _1415, 1.0), 0.0, 1.0);
    float _1439 = fast::clamp(fma(dot(-_1411, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1558 = fast::normalize(_773 + _1411);
    half _1502 = clamp(dot(_767, half3(_1411)), half(0.0), half(1.0));
    half3 _1598 = cross(_767, half3(_1558));
    half _1601 = clamp(dot(_767, half3(_1558)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1610 = half(params.facet_alpha) / fma(_1601, _1601, dot(_1598, _1598));
    half _1658 = half(1.0) - clamp(dot(half3(_1411), half3(_1558)), half(0.0), half(1.0));
    half _1661 = _1658 * _1658;
    half3 _1683 = (fma(half3(float3(params.facet_diffuseColor)), _1006, half4(_1126).xyz * (mix(half4(_1095).xxx, half4(_1095).yyy, half3(float3(params.facet_f0))) * _1114)) + min(fma((half3(float3(params.facet_f0)) + (_1353 * ((_1345 * _1345) * _1342))) * min(min((_1294 * _1294) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1186, _1318, _1056 * sqrt(fma(_1186 * _1186, _1314, _1308))), half(65504.0)), half(65504.0)), _1114, _1217) * (half4(frame.lightColor).xyz * _1186), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1353 * ((_1661 * _1661) * _1658))) * min(min((_1610 * _1610) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1502, _1318, _1056 * sqrt(fma(_1502 * _1502, _1314, _1308))), half(65504.0)), half(65504.0)), _1114, _1217) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1420) * half(_1420)) / fast::max(_1406, 9.9999997473787516355514526367188e-05)) * half(_1439)) * half(_1439)), float3(65504.0))) * _1502), half3(float3(65504.0)));
    float3 _1719 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1722 = dot(_1719, _1719);
    float3 _1727 = _1719 * rsqrt(fast::max(_1722, 9.9999999392252902907785028219223e-09));
    float _1731 = _1722 * float(frame.punctualLights[1].positionFalloff.w);
    float _1736 = fast::clamp(fma(-_1731, _1731, 1.0), 0.0, 1.0);
    float _1755 = fast::clamp(fma(dot(-_1727, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1874 = fast::normalize(_773 + _1727);
    half _1818 = clamp(dot(_767, half3(_1727)), half(0.0), half(1.0));
    half3 _1914 = cross(_767, half3(_1874));
    half _1917 = clamp(dot(_767, half3(_1874)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1926 = half(params.facet_alpha) / fma(_1917, _1917, dot(_1914, _1914));
    half _1974 = half(1.0) - clamp(dot(half3(_1727), half3(_1874)), half(0.0), half(1.0));
    half _1977 = _1974 * _1974;
    half3 _1999 = _1683 + min(fma((half3(float3(params.facet_f0)) + (_1353 * ((_1977 * _1977) * _1974))) * min(min((_1926 * _1926) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1818, _1318, _1056 * sqrt(fma(_1818 * _1818, _1314, _1308))), half(65504.0)), half(65504.0)), _1114, _1217) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1736) * half(_1736)) / fast::max(_1722, 9.9999997473787516355514526367188e-05)) * half(_1755)) * half(_1755)), float3(65504.0))) * _1818), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1999, half(1.0)));
    return out;
}

