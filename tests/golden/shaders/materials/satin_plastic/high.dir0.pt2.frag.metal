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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
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
    half3 _770 = normalize(half3(in.v_normal));
    float3 _786 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _943 = max(dot(_770, half3(_786)), half(9.9999997473787516355514526367188e-05));
    half3 _947 = reflect(-half3(_786), _770);
    float4 _979 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_943, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _958 = facet_environment.sample(facet_environmentSmplr, float3(_947), level(params.facet_environmentLod));
    float4 _1019 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_943, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1941 = half4(_1019);
    half _1032 = _1941.z;
    half _1034 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1032, half(1.0));
    half4 _1945 = half4(_1019);
    half _1039 = _1945.w;
    float4 _1048 = facet_environment.sample(facet_environmentSmplr, float3(_947), level(params.facet_sheenLod));
    float3 _1108 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1111 = dot(_1108, _1108);
    float3 _1116 = _1108 * rsqrt(fast::max(_1111, 9.9999999392252902907785028219223e-09));
    float _1120 = _1111 * float(frame.punctualLights[0].positionFalloff.w);
    float _1125 = fast::clamp(fma(-_1120, _1120, 1.0), 0.0, 1.0);
    float _1144 = fast::clamp(fma(dot(-_1116, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1155 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1125) * half(_1125)) / fast::max(_1111, 9.9999997473787516355514526367188e-05)) * half(_1144)) * half(_1144)), float3(65504.0));
    half _1207 = clamp(dot(_770, half3(_1116)), half(0.0), half(1.0));
    float3 _1269 = fast::normalize(_786 + _1116);
    half _1214 = clamp(dot(_770, half3(_1269)), half(0.0), half(1.0));
    half _1309 = half(4096.0) * half(params.facet_alpha);
    half4 _1334 = half4(cross(_770, half3(_1269)), half(params.facet_alpha) * _1214) * half(64.0);
    half _1315 = _1309 / dot(_1334, _1334);
    half _1347 = _1207 + _943;
    half _1359 = half(1.0) - clamp(dot(half3(_1116), half3(_1269)), half(0.0), half(1.0));
    half _1362 = _1359 * _1359;
    half3 _1370 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1403 = half(8192.0) * fma(half(-float(_1207)), _943, _1347);
    half _1407 = half(1.0) / (half(params.facet_sheenAlpha) * _1403);
    half _1414 = half(2048.0) * half(params.facet_sheenAlpha);
    half3 _1250 = min(fma((half3(float3(params.facet_f0)) + (_1370 * ((_1362 * _1362) * _1359))) * min(min((_1315 * _1315) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1207) * _943, _1347, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1155) * _1207) * _1034, (half3(float3(params.facet_sheenColor)) * ((((fma(_1407, _1403, half(2.0)) * pow(max(fma(half(-float(_1214)), _1214, half(1.0)), half(0.0)), half(0.5) * (_1407 * _1403))) * half(0.15915493667125701904296875)) * (_1207 * (_1407 * _1414))) * _1039)) * half3(_1155)), half3(float3(65504.0)));
    float3 _1472 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1475 = dot(_1472, _1472);
    float3 _1480 = _1472 * rsqrt(fast::max(_1475, 9.9999999392252902907785028219223e-09));
    float _1484 = _1475 * float(frame.punctualLights[1].positionFalloff.w);
    float _1489 = fast::clamp(fma(-_1484, _1484, 1.0), 0.0, 1.0);
    float _1508 = fast::clamp(fma(dot(-_1480, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1519 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1489) * half(_1489)) / fast::max(_1475, 9.9999997473787516355514526367188e-05)) * half(_1508)) * half(_1508)), float3(65504.0));
    half _1571 = clamp(dot(_770, half3(_1480)), half(0.0), half(1.0));
    float3 _1633 = fast::normalize(_786 + _1480);
    half _1578 = clamp(dot(_770, half3(_1633)), half(0.0), half(1.0));
    half4 _1698 = half4(cross(_770, half3(_1633)), half(params.facet_alpha) * _1578) * half(64.0);
    half _1679 = _1309 / dot(_1698, _1698);
    half _1711 = _1571 + _943;
    half _1723 = half(1.0) - clamp(dot(half3(_1480), half3(_1633)), half(0.0), half(1.0));
    half _1726 = _1723 * _1723;
    half _1767 = half(8192.0) * fma(half(-float(_1571)), _943, _1711);
    half _1771 = half(1.0) / (half(params.facet_sheenAlpha) * _1767);
    half3 _1614 = min(fma((half3(float3(params.facet_f0)) + (_1370 * ((_1726 * _1726) * _1723))) * min(min((_1679 * _1679) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1571) * _943, _1711, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1519) * _1571) * _1034, (half3(float3(params.facet_sheenColor)) * ((((fma(_1771, _1767, half(2.0)) * pow(max(fma(half(-float(_1578)), _1578, half(1.0)), half(0.0)), half(0.5) * (_1771 * _1767))) * half(0.15915493667125701904296875)) * (_1571 * (_1771 * _1414))) * _1039)) * half3(_1519)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1048).xyz, half3(float3(params.facet_sheenColor)) * _1032, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_958).xyz * mix(half4(_979).xxx, half4(_979).yyy, half3(float3(params.facet_f0)))) * _1034) + _1250) + _1614, half(1.0)));
    return out;
}

