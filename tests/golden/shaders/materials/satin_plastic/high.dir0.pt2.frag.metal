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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _783 = normalize(half3(in.v_normal));
    float3 _799 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _958 = max(dot(_783, half3(_799)), half(9.9999997473787516355514526367188e-05));
    half3 _962 = reflect(-half3(_799), _783);
    float4 _991 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_958, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1010 = facet_environment.sample(facet_environmentSmplr, float3(_962), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1042 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_958, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1968 = half4(_1042);
    half _1055 = _1968.z;
    half _1057 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1055, half(1.0));
    half4 _1972 = half4(_1042);
    half _1062 = _1972.w;
    float4 _1071 = facet_environment.sample(facet_environmentSmplr, float3(_962), level(params.facet_sheenLod));
    float3 _1131 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1134 = dot(_1131, _1131);
    float3 _1139 = _1131 * rsqrt(fast::max(_1134, 9.9999999392252902907785028219223e-09));
    float _1143 = _1134 * float(frame.punctualLights[0].positionFalloff.w);
    float _1148 = fast::clamp(fma(-_1143, _1143, 1.0), 0.0, 1.0);
    float _1167 = fast::clamp(fma(dot(-_1139, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1178 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1148) * half(_1148)) / fast::max(_1134, 9.9999997473787516355514526367188e-05)) * half(_1167)) * half(_1167)), float3(65504.0));
    float3 _1292 = fast::normalize(_799 + _1139);
    half _1233 = clamp(dot(_783, half3(_1139)), half(0.0), half(1.0));
    half _1237 = clamp(dot(_783, half3(_1292)), half(0.0), half(1.0));
    half _1332 = half(4096.0) * half(params.facet_alpha);
    half4 _1357 = half4(cross(_783, half3(_1292)), half(params.facet_alpha) * _1237) * half(64.0);
    half _1338 = _1332 / dot(_1357, _1357);
    half _1370 = _1233 + _958;
    half _1382 = half(1.0) - clamp(dot(half3(_1139), half3(_1292)), half(0.0), half(1.0));
    half _1385 = _1382 * _1382;
    half3 _1393 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1426 = half(8192.0) * fma(half(-float(_1233)), _958, _1370);
    half _1430 = half(1.0) / (half(params.facet_sheenAlpha) * _1426);
    half _1437 = half(2048.0) * half(params.facet_sheenAlpha);
    half3 _1273 = min(fma((half3(float3(params.facet_f0)) + (_1393 * ((_1385 * _1385) * _1382))) * min(min((_1338 * _1338) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1233) * _958, _1370, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1178) * _1233) * _1057, (half3(float3(params.facet_sheenColor)) * ((((fma(_1430, _1426, half(2.0)) * pow(max(fma(half(-float(_1237)), _1237, half(1.0)), half(0.0)), half(0.5) * (_1430 * _1426))) * half(0.15915493667125701904296875)) * (_1233 * (_1430 * _1437))) * _1062)) * half3(_1178)), half3(float3(65504.0)));
    float3 _1495 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1498 = dot(_1495, _1495);
    float3 _1503 = _1495 * rsqrt(fast::max(_1498, 9.9999999392252902907785028219223e-09));
    float _1507 = _1498 * float(frame.punctualLights[1].positionFalloff.w);
    float _1512 = fast::clamp(fma(-_1507, _1507, 1.0), 0.0, 1.0);
    float _1531 = fast::clamp(fma(dot(-_1503, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1542 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1512) * half(_1512)) / fast::max(_1498, 9.9999997473787516355514526367188e-05)) * half(_1531)) * half(_1531)), float3(65504.0));
    float3 _1656 = fast::normalize(_799 + _1503);
    half _1597 = clamp(dot(_783, half3(_1503)), half(0.0), half(1.0));
    half _1601 = clamp(dot(_783, half3(_1656)), half(0.0), half(1.0));
    half4 _1721 = half4(cross(_783, half3(_1656)), half(params.facet_alpha) * _1601) * half(64.0);
    half _1702 = _1332 / dot(_1721, _1721);
    half _1734 = _1597 + _958;
    half _1746 = half(1.0) - clamp(dot(half3(_1503), half3(_1656)), half(0.0), half(1.0));
    half _1749 = _1746 * _1746;
    half _1790 = half(8192.0) * fma(half(-float(_1597)), _958, _1734);
    half _1794 = half(1.0) / (half(params.facet_sheenAlpha) * _1790);
    half3 _1637 = min(fma((half3(float3(params.facet_f0)) + (_1393 * ((_1749 * _1749) * _1746))) * min(min((_1702 * _1702) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1597) * _958, _1734, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1542) * _1597) * _1057, (half3(float3(params.facet_sheenColor)) * ((((fma(_1794, _1790, half(2.0)) * pow(max(fma(half(-float(_1601)), _1601, half(1.0)), half(0.0)), half(0.5) * (_1794 * _1790))) * half(0.15915493667125701904296875)) * (_1597 * (_1794 * _1437))) * _1062)) * half3(_1542)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1071).xyz, half3(float3(params.facet_sheenColor)) * _1055, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1010).xyz * mix(half4(_991).xxx, half4(_991).yyy, half3(float3(params.facet_f0)))) * _1057) + _1273) + _1637, half(1.0)));
    return out;
}

