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
    half3 _734 = normalize(half3(in.v_normal));
    float3 _750 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _930 = max(dot(_734, half3(_750)), half(9.9999997473787516355514526367188e-05));
    half3 _934 = reflect(-half3(_750), _734);
    float4 _966 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_930, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _945 = facet_environment.sample(facet_environmentSmplr, float3(_934), level(params.facet_environmentLod));
    float4 _1006 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_930, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2111 = half4(_1006);
    half _1019 = _2111.z;
    half _1021 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1019, half(1.0));
    half4 _2115 = half4(_1006);
    half _1026 = _2115.w;
    float4 _1035 = facet_environment.sample(facet_environmentSmplr, float3(_934), level(params.facet_sheenLod));
    half3 _796 = half4(frame.lightDirection).xyz;
    half3 _808 = half4(frame.lightColor).xyz;
    half _1110 = clamp(dot(_734, _796), half(0.0), half(1.0));
    half3 _1171 = normalize(half3(_750) + _796);
    half _1117 = clamp(dot(_734, _1171), half(0.0), half(1.0));
    half _1121 = clamp(dot(_796, _1171), half(0.0), half(1.0));
    half _1203 = max(_1121 * _1121, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1226 = half4(cross(_734, _1171), half(params.facet_alpha) * _1117) * half(64.0);
    half _1237 = half(params.facet_ggxAlphaScaled) / (dot(_1226, _1226) * _1203);
    half _1273 = half(8192.0) * fma(half(-float(_1110)), _930, _1110 + _930);
    half _1277 = half(1.0) / (half(params.facet_sheenAlpha) * _1273);
    half _1284 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1342 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1345 = dot(_1342, _1342);
    float3 _1350 = _1342 * rsqrt(fast::max(_1345, 9.9999999392252902907785028219223e-09));
    float _1354 = _1345 * float(frame.punctualLights[0].positionFalloff.w);
    float _1359 = fast::clamp(fma(-_1354, _1354, 1.0), 0.0, 1.0);
    float _1378 = fast::clamp(fma(dot(-_1350, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1389 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1359) * half(_1359)) / fast::max(_1345, 9.9999997473787516355514526367188e-05)) * half(_1378)) * half(_1378)), float3(65504.0));
    half _1441 = clamp(dot(_734, half3(_1350)), half(0.0), half(1.0));
    half3 _1502 = normalize(half3(_750) + half3(_1350));
    half _1448 = clamp(dot(_734, _1502), half(0.0), half(1.0));
    half _1452 = clamp(dot(half3(_1350), _1502), half(0.0), half(1.0));
    half _1534 = max(_1452 * _1452, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1557 = half4(cross(_734, _1502), half(params.facet_alpha) * _1448) * half(64.0);
    half _1568 = half(params.facet_ggxAlphaScaled) / (dot(_1557, _1557) * _1534);
    half _1604 = half(8192.0) * fma(half(-float(_1441)), _930, _1441 + _930);
    half _1608 = half(1.0) / (half(params.facet_sheenAlpha) * _1604);
    half3 _1637 = (fma(half4(_1035).xyz, half3(float3(params.facet_sheenColor)) * _1019, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_945).xyz * mix(half4(_966).xxx, half4(_966).yyy, half3(float3(params.facet_f0)))) * _1021) + min(fma(half3(float3(params.facet_f0)) * min((_1237 * _1237) * _1203, half(65504.0)), (_808 * _1110) * _1021, (half3(float3(params.facet_sheenColor)) * ((((fma(_1277, _1273, half(2.0)) * pow(max(fma(half(-float(_1117)), _1117, half(1.0)), half(0.0)), half(0.5) * (_1277 * _1273))) * half(0.15915493667125701904296875)) * (_1110 * (_1277 * _1284))) * _1026)) * _808), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min((_1568 * _1568) * _1534, half(65504.0)), (half3(_1389) * _1441) * _1021, (half3(float3(params.facet_sheenColor)) * ((((fma(_1608, _1604, half(2.0)) * pow(max(fma(half(-float(_1448)), _1448, half(1.0)), half(0.0)), half(0.5) * (_1608 * _1604))) * half(0.15915493667125701904296875)) * (_1441 * (_1608 * _1284))) * _1026)) * half3(_1389)), half3(float3(65504.0)));
    float3 _1673 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1676 = dot(_1673, _1673);
    float3 _1681 = _1673 * rsqrt(fast::max(_1676, 9.9999999392252902907785028219223e-09));
    float _1685 = _1676 * float(frame.punctualLights[1].positionFalloff.w);
    float _1690 = fast::clamp(fma(-_1685, _1685, 1.0), 0.0, 1.0);
    float _1709 = fast::clamp(fma(dot(-_1681, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1720 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1690) * half(_1690)) / fast::max(_1676, 9.9999997473787516355514526367188e-05)) * half(_1709)) * half(_1709)), float3(65504.0));
    half _1772 = clamp(dot(_734, half3(_1681)), half(0.0), half(1.0));
    half3 _1833 = normalize(half3(_750) + half3(_1681));
    half _1779 = clamp(dot(_734, _1833), half(0.0), half(1.0));
    half _1783 = clamp(dot(half3(_1681), _1833), half(0.0), half(1.0));
    half _1865 = max(_1783 * _1783, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1888 = half4(cross(_734, _1833), half(params.facet_alpha) * _1779) * half(64.0);
    half _1899 = half(params.facet_ggxAlphaScaled) / (dot(_1888, _1888) * _1865);
    half _1935 = half(8192.0) * fma(half(-float(_1772)), _930, _1772 + _930);
    half _1939 = half(1.0) / (half(params.facet_sheenAlpha) * _1935);
    out.fragColor = float4(half4(_1637 + min(fma(half3(float3(params.facet_f0)) * min((_1899 * _1899) * _1865, half(65504.0)), (half3(_1720) * _1772) * _1021, (half3(float3(params.facet_sheenColor)) * ((((fma(_1939, _1935, half(2.0)) * pow(max(fma(half(-float(_1779)), _1779, half(1.0)), half(0.0)), half(0.5) * (_1939 * _1935))) * half(0.15915493667125701904296875)) * (_1772 * (_1939 * _1284))) * _1026)) * half3(_1720)), half3(float3(65504.0))), half(1.0)));
    return out;
}

