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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _712 = normalize(half3(in.v_normal));
    float3 _728 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _911 = max(dot(_712, half3(_728)), half(9.9999997473787516355514526367188e-05));
    half3 _915 = reflect(-half3(_728), _712);
    float4 _945 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_911, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _954 = mix(half4(_945).xxx, half4(_945).yyy, half3(float3(params.facet_f0)));
    float4 _964 = facet_environment.sample(facet_environmentSmplr, float3(_915), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _996 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_911, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2021 = half4(_996);
    half _1009 = _2021.z;
    half _1011 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1009, half(1.0));
    half4 _2025 = half4(_996);
    half _1016 = _2025.w;
    float4 _1025 = facet_environment.sample(facet_environmentSmplr, float3(_915), level(params.facet_sheenLod));
    half3 _774 = half4(frame.lightDirection).xyz;
    half3 _786 = half4(frame.lightColor).xyz;
    half _1103 = clamp(dot(_712, _774), half(0.0), half(1.0));
    half _1107 = clamp(dot(_712, normalize(half3(_728) + _774)), half(0.0), half(1.0));
    half _1186 = clamp(dot(_915, _774), half(0.0), half(1.0));
    half _1189 = _1186 * _1186;
    half4 _2043 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1189 * _1189, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1201 = _2043.x;
    half _1235 = half(8192.0) * fma(half(-float(_1103)), _911, _1103 + _911);
    half _1239 = half(1.0) / (half(params.facet_sheenAlpha) * _1235);
    half _1246 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1304 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1307 = dot(_1304, _1304);
    float3 _1312 = _1304 * rsqrt(fast::max(_1307, 9.9999999392252902907785028219223e-09));
    float _1316 = _1307 * float(frame.punctualLights[0].positionFalloff.w);
    float _1321 = fast::clamp(fma(-_1316, _1316, 1.0), 0.0, 1.0);
    float _1340 = fast::clamp(fma(dot(-_1312, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1351 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1321) * half(_1321)) / fast::max(_1307, 9.9999997473787516355514526367188e-05)) * half(_1340)) * half(_1340)), float3(65504.0));
    half _1406 = clamp(dot(_712, half3(_1312)), half(0.0), half(1.0));
    half _1410 = clamp(dot(_712, normalize(half3(_728) + half3(_1312))), half(0.0), half(1.0));
    half _1489 = clamp(dot(_915, half3(_1312)), half(0.0), half(1.0));
    half _1492 = _1489 * _1489;
    half4 _2087 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1492 * _1492, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1504 = _2087.x;
    half _1538 = half(8192.0) * fma(half(-float(_1406)), _911, _1406 + _911);
    half _1542 = half(1.0) / (half(params.facet_sheenAlpha) * _1538);
    half3 _1571 = (fma(half4(_1025).xyz, half3(float3(params.facet_sheenColor)) * _1009, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_964).xyz * _954) * _1011) + min(fma(_954 * ((_1201 * _1201) * half(5.092957973480224609375)), (_786 * _1103) * _1011, (half3(float3(params.facet_sheenColor)) * ((((fma(_1239, _1235, half(2.0)) * pow(max(fma(half(-float(_1107)), _1107, half(1.0)), half(0.0)), half(0.5) * (_1239 * _1235))) * half(0.15915493667125701904296875)) * (_1103 * (_1239 * _1246))) * _1016)) * _786), half3(float3(65504.0)))) + min(fma(_954 * ((_1504 * _1504) * half(5.092957973480224609375)), (half3(_1351) * _1406) * _1011, (half3(float3(params.facet_sheenColor)) * ((((fma(_1542, _1538, half(2.0)) * pow(max(fma(half(-float(_1410)), _1410, half(1.0)), half(0.0)), half(0.5) * (_1542 * _1538))) * half(0.15915493667125701904296875)) * (_1406 * (_1542 * _1246))) * _1016)) * half3(_1351)), half3(float3(65504.0)));
    float3 _1607 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1610 = dot(_1607, _1607);
    float3 _1615 = _1607 * rsqrt(fast::max(_1610, 9.9999999392252902907785028219223e-09));
    float _1619 = _1610 * float(frame.punctualLights[1].positionFalloff.w);
    float _1624 = fast::clamp(fma(-_1619, _1619, 1.0), 0.0, 1.0);
    float _1643 = fast::clamp(fma(dot(-_1615, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1654 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1624) * half(_1624)) / fast::max(_1610, 9.9999997473787516355514526367188e-05)) * half(_1643)) * half(_1643)), float3(65504.0));
    half _1709 = clamp(dot(_712, half3(_1615)), half(0.0), half(1.0));
    half _1713 = clamp(dot(_712, normalize(half3(_728) + half3(_1615))), half(0.0), half(1.0));
    half _1792 = clamp(dot(_915, half3(_1615)), half(0.0), half(1.0));
    half _1795 = _1792 * _1792;
    half4 _2131 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1795 * _1795, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1807 = _2131.x;
    half _1841 = half(8192.0) * fma(half(-float(_1709)), _911, _1709 + _911);
    half _1845 = half(1.0) / (half(params.facet_sheenAlpha) * _1841);
    out.fragColor = float4(half4(_1571 + min(fma(_954 * ((_1807 * _1807) * half(5.092957973480224609375)), (half3(_1654) * _1709) * _1011, (half3(float3(params.facet_sheenColor)) * ((((fma(_1845, _1841, half(2.0)) * pow(max(fma(half(-float(_1713)), _1713, half(1.0)), half(0.0)), half(0.5) * (_1845 * _1841))) * half(0.15915493667125701904296875)) * (_1709 * (_1845 * _1246))) * _1016)) * half3(_1654)), half3(float3(65504.0))), half(1.0)));
    return out;
}

