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
    half3 _770 = normalize(half3(in.v_normal));
    float3 _786 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _947 = max(dot(_770, half3(_786)), half(9.9999997473787516355514526367188e-05));
    half3 _951 = reflect(-half3(_786), _770);
    float4 _986 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_947, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1005 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_986).y) - half(1.0)));
    float4 _1015 = facet_environment.sample(facet_environmentSmplr, float3(_951), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1047 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_947, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1919 = half4(_1047);
    half _1060 = _1919.z;
    half _1062 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1060, half(1.0));
    half4 _1923 = half4(_1047);
    half _1067 = _1923.w;
    float4 _1076 = facet_environment.sample(facet_environmentSmplr, float3(_951), level(params.facet_sheenLod));
    float3 _1136 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1139 = dot(_1136, _1136);
    float3 _1144 = _1136 * rsqrt(fast::max(_1139, 9.9999999392252902907785028219223e-09));
    float _1148 = _1139 * float(frame.punctualLights[0].positionFalloff.w);
    float _1153 = fast::clamp(fma(-_1148, _1148, 1.0), 0.0, 1.0);
    float _1172 = fast::clamp(fma(dot(-_1144, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1183 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1153) * half(_1153)) / fast::max(_1139, 9.9999997473787516355514526367188e-05)) * half(_1172)) * half(_1172)), float3(65504.0));
    half3 _1299 = normalize(half3(_786) + half3(_1144));
    half _1238 = clamp(dot(_770, half3(_1144)), half(0.0), half(1.0));
    half _1242 = clamp(dot(_770, _1299), half(0.0), half(1.0));
    half4 _1368 = half4(cross(_770, _1299), half(params.facet_alpha) * _1242) * half(64.0);
    half _1337 = _1238 + _947;
    half _1342 = half(4096.0) * half(params.facet_alpha);
    half _1345 = half(6.283185482025146484375) * max(mix((half(2.0) * _1238) * _947, _1337, half(params.facet_alpha)), half(0.000244140625));
    half _1347 = _1342 / (dot(_1368, _1368) * _1345);
    half _1401 = half(8192.0) * fma(half(-float(_1238)), _947, _1337);
    half _1405 = half(1.0) / (half(params.facet_sheenAlpha) * _1401);
    half _1412 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1470 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1473 = dot(_1470, _1470);
    float3 _1478 = _1470 * rsqrt(fast::max(_1473, 9.9999999392252902907785028219223e-09));
    float _1482 = _1473 * float(frame.punctualLights[1].positionFalloff.w);
    float _1487 = fast::clamp(fma(-_1482, _1482, 1.0), 0.0, 1.0);
    float _1506 = fast::clamp(fma(dot(-_1478, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1517 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1487) * half(_1487)) / fast::max(_1473, 9.9999997473787516355514526367188e-05)) * half(_1506)) * half(_1506)), float3(65504.0));
    half3 _1633 = normalize(half3(_786) + half3(_1478));
    half _1572 = clamp(dot(_770, half3(_1478)), half(0.0), half(1.0));
    half _1576 = clamp(dot(_770, _1633), half(0.0), half(1.0));
    half4 _1702 = half4(cross(_770, _1633), half(params.facet_alpha) * _1576) * half(64.0);
    half _1671 = _1572 + _947;
    half _1679 = half(6.283185482025146484375) * max(mix((half(2.0) * _1572) * _947, _1671, half(params.facet_alpha)), half(0.000244140625));
    half _1681 = _1342 / (dot(_1702, _1702) * _1679);
    half _1735 = half(8192.0) * fma(half(-float(_1572)), _947, _1671);
    half _1739 = half(1.0) / (half(params.facet_sheenAlpha) * _1735);
    half3 _1768 = (fma(half4(_1076).xyz, half3(float3(params.facet_sheenColor)) * _1060, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1015).xyz * (mix(half4(_986).xxx, half4(_986).yyy, half3(float3(params.facet_f0))) * _1005)) * _1062) + min(fma((half3(float3(params.facet_f0)) * min(_1347 * (_1347 * _1345), half(65504.0))) * _1005, (half3(_1183) * _1238) * _1062, (half3(float3(params.facet_sheenColor)) * ((((fma(_1405, _1401, half(2.0)) * pow(max(fma(half(-float(_1242)), _1242, half(1.0)), half(0.0)), half(0.5) * (_1405 * _1401))) * half(0.15915493667125701904296875)) * (_1238 * (_1405 * _1412))) * _1067)) * half3(_1183)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1681 * (_1681 * _1679), half(65504.0))) * _1005, (half3(_1517) * _1572) * _1062, (half3(float3(params.facet_sheenColor)) * ((((fma(_1739, _1735, half(2.0)) * pow(max(fma(half(-float(_1576)), _1576, half(1.0)), half(0.0)), half(0.5) * (_1739 * _1735))) * half(0.15915493667125701904296875)) * (_1572 * (_1739 * _1412))) * _1067)) * half3(_1517)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1768, half(1.0)));
    return out;
}

