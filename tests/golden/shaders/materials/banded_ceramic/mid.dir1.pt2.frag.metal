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
    float _798 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _906 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _798)), half(0.0), half(1.0));
    half3 _914 = half3((half(0.1599999964237213134765625) * _906) * _906);
    half _923 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _798)), half(0.08900000154972076416015625), half(1.0));
    half _866 = max(dot(_633, half3(_649)), half(9.9999997473787516355514526367188e-05));
    float4 _930 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_866, _923)), level(0.0));
    half3 _949 = half3(float3(1.0)) + (_914 * ((half(1.0) / half4(_930).y) - half(1.0)));
    float4 _956 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_649), _633)), level(_923 * half(4.0)));
    half3 _686 = half4(frame.lightDirection).xyz;
    half _1087 = _923 * _923;
    half3 _1098 = normalize(half3(_649) + _686);
    half _1014 = clamp(dot(_633, _686), half(0.0), half(1.0));
    half3 _1125 = cross(_633, _1098);
    half _1128 = clamp(dot(_633, _1098), half(0.0), half(1.0)) * _1087;
    half _1145 = max(mix((half(2.0) * _1014) * _866, _1014 + _866, _1087), half(0.000244140625));
    half _1147 = half(1024.0) * _1087;
    half _1152 = _1147 / (fma(_1128, _1128, dot(_1125, _1125)) * (half(6433.98193359375) * _1145));
    float3 _1200 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1203 = dot(_1200, _1200);
    float3 _1208 = _1200 * rsqrt(fast::max(_1203, 9.9999999392252902907785028219223e-09));
    float _1212 = _1203 * float(frame.punctualLights[0].positionFalloff.w);
    float _1217 = fast::clamp(fma(-_1212, _1212, 1.0), 0.0, 1.0);
    float _1236 = fast::clamp(fma(dot(-_1208, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1381 = normalize(half3(_649) + half3(_1208));
    half _1297 = clamp(dot(_633, half3(_1208)), half(0.0), half(1.0));
    half3 _1408 = cross(_633, _1381);
    half _1411 = clamp(dot(_633, _1381), half(0.0), half(1.0)) * _1087;
    half _1428 = max(mix((half(2.0) * _1297) * _866, _1297 + _866, _1087), half(0.000244140625));
    half _1435 = _1147 / (fma(_1411, _1411, dot(_1408, _1408)) * (half(6433.98193359375) * _1428));
    float3 _1483 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1486 = dot(_1483, _1483);
    float3 _1491 = _1483 * rsqrt(fast::max(_1486, 9.9999999392252902907785028219223e-09));
    float _1495 = _1486 * float(frame.punctualLights[1].positionFalloff.w);
    float _1500 = fast::clamp(fma(-_1495, _1495, 1.0), 0.0, 1.0);
    float _1519 = fast::clamp(fma(dot(-_1491, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1664 = normalize(half3(_649) + half3(_1491));
    half _1580 = clamp(dot(_633, half3(_1491)), half(0.0), half(1.0));
    half3 _1691 = cross(_633, _1664);
    half _1694 = clamp(dot(_633, _1664), half(0.0), half(1.0)) * _1087;
    half _1711 = max(mix((half(2.0) * _1580) * _866, _1580 + _866, _1087), half(0.000244140625));
    half _1718 = _1147 / (fma(_1694, _1694, dot(_1691, _1691)) * (half(6433.98193359375) * _1711));
    half3 _1730 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_798))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_956).xyz * (mix(half4(_930).xxx, half4(_930).yyy, _914) * _949)) + min(((_914 * min(_1152 * (_1152 * (half(6.283185482025146484375) * _1145)), half(65504.0))) * _949) * (half4(frame.lightColor).xyz * _1014), half3(float3(65504.0)))) + min(((_914 * min(_1435 * (_1435 * (half(6.283185482025146484375) * _1428)), half(65504.0))) * _949) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1217) * half(_1217)) / fast::max(_1203, 9.9999997473787516355514526367188e-05)) * half(_1236)) * half(_1236)), float3(65504.0))) * _1297), half3(float3(65504.0)))) + min(((_914 * min(_1718 * (_1718 * (half(6.283185482025146484375) * _1711)), half(65504.0))) * _949) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1500) * half(_1500)) / fast::max(_1486, 9.9999997473787516355514526367188e-05)) * half(_1519)) * half(_1519)), float3(65504.0))) * _1580), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1730, half(1.0)));
    return out;
}

