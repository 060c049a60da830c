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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _745 = normalize(half3(in.v_normal));
    float3 _752 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _858 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _907 = _745.y;
    half _912 = _745.z;
    half _917 = _745.x;
    half3 _985 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _907)) + (half4(frame.sh[2]).xyz * _912)) + (half4(frame.sh[3]).xyz * _917)) + (((((half4(frame.sh[4]).xyz * (_917 * _907)) + (half4(frame.sh[5]).xyz * (_907 * _912))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _912, _912, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_917 * _912))) + (half4(frame.sh[8]).xyz * fma(_917, _917, half(-float(_907 * _907))))), half3(float3(0.0)));
    half3 _1008 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_858))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1083 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _858)), half(0.0), half(1.0));
    half3 _1091 = half3((half(0.1599999964237213134765625) * _1083) * _1083);
    half _1100 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _858)), half(0.08900000154972076416015625), half(1.0));
    half _1043 = max(dot(_745, half3(_752)), half(9.9999997473787516355514526367188e-05));
    float4 _1107 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1043, _1100)), level(0.0));
    half3 _1126 = half3(float3(1.0)) + (_1091 * ((half(1.0) / half4(_1107).y) - half(1.0)));
    float4 _1136 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_752), _745)), level(_1100 * (half(4.0) * (half(2.0) - _1100))));
    half _1275 = _1100 * _1100;
    float3 _1287 = fast::normalize(_752 + frame.lightDirection.xyz);
    half _1196 = clamp(dot(_745, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1327 = cross(_745, half3(_1287));
    half _1330 = clamp(dot(_745, half3(_1287)), half(0.0), half(1.0)) * _1275;
    half _1339 = _1275 / fma(_1330, _1330, dot(_1327, _1327));
    half _1353 = _1275 * _1275;
    half _1359 = fma(half(-float(_1275)), _1275, half(1.0));
    half _1387 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1287)), half(0.0), half(1.0));
    half _1390 = _1387 * _1387;
    half3 _1420 = fma(_1008, _985, half4(_1136).xyz * (mix(half4(_1107).xxx, half4(_1107).yyy, _1091) * _1126)) + min(fma((_1091 + ((half3(float3(1.0)) - _1091) * ((_1390 * _1390) * _1387))) * min(min((_1339 * _1339) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1196, sqrt(fma(_1043 * _1043, _1359, _1353)), _1043 * sqrt(fma(_1196 * _1196, _1359, _1353))), half(65504.0)), half(65504.0)), _1126, _1008 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1196), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1420, half(1.0)));
    return out;
}

