#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    half3 _698 = normalize(half3(in.v_normal));
    float3 _714 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _860 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _960 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _860)), half(0.0), half(1.0));
    half3 _968 = half3((half(0.1599999964237213134765625) * _960) * _960);
    half _977 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _860)), half(0.08900000154972076416015625), half(1.0));
    float4 _984 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_698, half3(_714)), half(9.9999997473787516355514526367188e-05)), _977)), level(0.0));
    float4 _1003 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_714), _698)), level(_977 * (half(4.0) * (half(2.0) - _977))));
    half3 _751 = half4(frame.lightDirection).xyz;
    half _1154 = _977 * _977;
    half3 _1064 = half3(_714) + _751;
    half3 _1074 = _1064 * (half(64.0) * rsqrt(dot(_1064, _1064)));
    half _1083 = clamp(dot(_751, _1074) * half(0.015625), half(0.0), half(1.0));
    half4 _1311 = half4(cross(_698, _1074), _1154 * clamp(dot(_698, _1074), half(0.0), half(64.0)));
    half _1331 = fma(half(-0.3125), _1154, half(1.00820004940032958984375));
    half _1332 = (half(12.56637096405029296875) * max(_1083 * _1083, half(0.1500000059604644775390625))) * _1331;
    half _1344 = _1154 / ((dot(_1311, _1311) * half(0.000244140625)) * _1332);
    float3 _1391 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1394 = dot(_1391, _1391);
    float3 _1399 = _1391 * rsqrt(fast::max(_1394, 9.9999999392252902907785028219223e-09));
    float _1403 = _1394 * float(frame.punctualLights[0].positionFalloff.w);
    float _1408 = fast::clamp(fma(-_1403, _1403, 1.0), 0.0, 1.0);
    float _1427 = fast::clamp(fma(dot(-_1399, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1491 = half3(_714) + half3(_1399);
    half3 _1501 = _1491 * (half(64.0) * rsqrt(dot(_1491, _1491)));
    half _1510 = clamp(dot(half3(_1399), _1501) * half(0.015625), half(0.0), half(1.0));
    half4 _1738 = half4(cross(_698, _1501), _1154 * clamp(dot(_698, _1501), half(0.0), half(64.0)));
    half _1759 = (half(12.56637096405029296875) * max(_1510 * _1510, half(0.1500000059604644775390625))) * _1331;
    half _1771 = _1154 / ((dot(_1738, _1738) * half(0.000244140625)) * _1759);
    float3 _1818 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1821 = dot(_1818, _1818);
    float3 _1826 = _1818 * rsqrt(fast::max(_1821, 9.9999999392252902907785028219223e-09));
    float _1830 = _1821 * float(frame.punctualLights[1].positionFalloff.w);
    float _1835 = fast::clamp(fma(-_1830, _1830, 1.0), 0.0, 1.0);
    float _1854 = fast::clamp(fma(dot(-_1826, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1918 = half3(_714) + half3(_1826);
    half3 _1928 = _1918 * (half(64.0) * rsqrt(dot(_1918, _1918)));
    half _1937 = clamp(dot(half3(_1826), _1928) * half(0.015625), half(0.0), half(1.0));
    half4 _2165 = half4(cross(_698, _1928), _1154 * clamp(dot(_698, _1928), half(0.0), half(64.0)));
    half _2186 = (half(12.56637096405029296875) * max(_1937 * _1937, half(0.1500000059604644775390625))) * _1331;
    half _2198 = _1154 / ((dot(_2165, _2165) * half(0.000244140625)) * _2186);
    half3 _2209 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_860))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1003).xyz * mix(half4(_984).xxx, half4(_984).yyy, _968)) + min((_968 * half4(frame.lightColor).xyz) * (min((_1344 * _1344) * _1332, half(65504.0)) * clamp(dot(_698, _751), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_968 * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1408) * half(_1408)) / fast::max(_1394, 9.9999997473787516355514526367188e-05)) * half(_1427)) * half(_1427)), float3(65504.0)))) * (min((_1771 * _1771) * _1759, half(65504.0)) * clamp(dot(_698, half3(_1399)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_968 * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1835) * half(_1835)) / fast::max(_1821, 9.9999997473787516355514526367188e-05)) * half(_1854)) * half(_1854)), float3(65504.0)))) * (min((_2198 * _2198) * _2186, half(65504.0)) * clamp(dot(_698, half3(_1826)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2209, half(1.0)));
    return out;
}

