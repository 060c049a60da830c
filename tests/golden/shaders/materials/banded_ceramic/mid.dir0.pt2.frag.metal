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
    half3 _633 = normalize(half3(in.v_normal));
    float3 _649 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _774 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _882 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _774)), half(0.0), half(1.0));
    half3 _890 = half3((half(0.1599999964237213134765625) * _882) * _882);
    half _899 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _774)), half(0.08900000154972076416015625), half(1.0));
    half _842 = max(dot(_633, half3(_649)), half(9.9999997473787516355514526367188e-05));
    float4 _906 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_842, _899)), level(0.0));
    half3 _925 = half3(float3(1.0)) + (_890 * ((half(1.0) / half4(_906).y) - half(1.0)));
    float4 _932 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_649), _633)), level(_899 * half(4.0)));
    float3 _977 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _980 = dot(_977, _977);
    float3 _985 = _977 * rsqrt(fast::max(_980, 9.9999999392252902907785028219223e-09));
    float _989 = _980 * float(frame.punctualLights[0].positionFalloff.w);
    float _994 = fast::clamp(fma(-_989, _989, 1.0), 0.0, 1.0);
    float _1013 = fast::clamp(fma(dot(-_985, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1147 = _899 * _899;
    half3 _1158 = normalize(half3(_649) + half3(_985));
    half _1074 = clamp(dot(_633, half3(_985)), half(0.0), half(1.0));
    half3 _1185 = cross(_633, _1158);
    half _1188 = clamp(dot(_633, _1158), half(0.0), half(1.0)) * _1147;
    half _1205 = max(mix((half(2.0) * _1074) * _842, _1074 + _842, _1147), half(0.000244140625));
    half _1207 = half(1024.0) * _1147;
    half _1212 = _1207 / (fma(_1188, _1188, dot(_1185, _1185)) * (half(6433.98193359375) * _1205));
    float3 _1260 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1263 = dot(_1260, _1260);
    float3 _1268 = _1260 * rsqrt(fast::max(_1263, 9.9999999392252902907785028219223e-09));
    float _1272 = _1263 * float(frame.punctualLights[1].positionFalloff.w);
    float _1277 = fast::clamp(fma(-_1272, _1272, 1.0), 0.0, 1.0);
    float _1296 = fast::clamp(fma(dot(-_1268, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1441 = normalize(half3(_649) + half3(_1268));
    half _1357 = clamp(dot(_633, half3(_1268)), half(0.0), half(1.0));
    half3 _1468 = cross(_633, _1441);
    half _1471 = clamp(dot(_633, _1441), half(0.0), half(1.0)) * _1147;
    half _1488 = max(mix((half(2.0) * _1357) * _842, _1357 + _842, _1147), half(0.000244140625));
    half _1495 = _1207 / (fma(_1471, _1471, dot(_1468, _1468)) * (half(6433.98193359375) * _1488));
    half3 _1507 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_774))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_932).xyz * (mix(half4(_906).xxx, half4(_906).yyy, _890) * _925)) + min(((_890 * min(_1212 * (_1212 * (half(6.283185482025146484375) * _1205)), half(65504.0))) * _925) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_994) * half(_994)) / fast::max(_980, 9.9999997473787516355514526367188e-05)) * half(_1013)) * half(_1013)), float3(65504.0))) * _1074), half3(float3(65504.0)))) + min(((_890 * min(_1495 * (_1495 * (half(6.283185482025146484375) * _1488)), half(65504.0))) * _925) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1277) * half(_1277)) / fast::max(_1263, 9.9999997473787516355514526367188e-05)) * half(_1296)) * half(_1296)), float3(65504.0))) * _1357), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1507, half(1.0)));
    return out;
}

