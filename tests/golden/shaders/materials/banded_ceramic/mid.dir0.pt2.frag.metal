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
    half3 _638 = normalize(half3(in.v_normal));
    float3 _654 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _779 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _887 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _779)), half(0.0), half(1.0));
    half3 _895 = half3((half(0.1599999964237213134765625) * _887) * _887);
    half _904 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _779)), half(0.08900000154972076416015625), half(1.0));
    half _847 = max(dot(_638, half3(_654)), half(9.9999997473787516355514526367188e-05));
    float4 _911 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_847, _904)), level(0.0));
    half3 _930 = half3(float3(1.0)) + (_895 * ((half(1.0) / half4(_911).y) - half(1.0)));
    float4 _942 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_654), _638)), level(_904 * (half(4.0) * (half(2.0) - _904))));
    float3 _987 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _990 = dot(_987, _987);
    float3 _995 = _987 * rsqrt(fast::max(_990, 9.9999999392252902907785028219223e-09));
    float _999 = _990 * float(frame.punctualLights[0].positionFalloff.w);
    float _1004 = fast::clamp(fma(-_999, _999, 1.0), 0.0, 1.0);
    float _1023 = fast::clamp(fma(dot(-_995, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1157 = _904 * _904;
    half3 _1168 = normalize(half3(_654) + half3(_995));
    half _1084 = clamp(dot(_638, half3(_995)), half(0.0), half(1.0));
    half3 _1195 = cross(_638, _1168);
    half _1198 = clamp(dot(_638, _1168), half(0.0), half(1.0)) * _1157;
    half _1215 = max(mix((half(2.0) * _1084) * _847, _1084 + _847, _1157), half(0.000244140625));
    half _1217 = half(1024.0) * _1157;
    half _1222 = _1217 / (fma(_1198, _1198, dot(_1195, _1195)) * (half(6433.98193359375) * _1215));
    float3 _1270 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1273 = dot(_1270, _1270);
    float3 _1278 = _1270 * rsqrt(fast::max(_1273, 9.9999999392252902907785028219223e-09));
    float _1282 = _1273 * float(frame.punctualLights[1].positionFalloff.w);
    float _1287 = fast::clamp(fma(-_1282, _1282, 1.0), 0.0, 1.0);
    float _1306 = fast::clamp(fma(dot(-_1278, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1451 = normalize(half3(_654) + half3(_1278));
    half _1367 = clamp(dot(_638, half3(_1278)), half(0.0), half(1.0));
    half3 _1478 = cross(_638, _1451);
    half _1481 = clamp(dot(_638, _1451), half(0.0), half(1.0)) * _1157;
    half _1498 = max(mix((half(2.0) * _1367) * _847, _1367 + _847, _1157), half(0.000244140625));
    half _1505 = _1217 / (fma(_1481, _1481, dot(_1478, _1478)) * (half(6433.98193359375) * _1498));
    half3 _1517 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_779))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_942).xyz * (mix(half4(_911).xxx, half4(_911).yyy, _895) * _930)) + min(((_895 * min(_1222 * (_1222 * (half(6.283185482025146484375) * _1215)), half(65504.0))) * _930) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1004) * half(_1004)) / fast::max(_990, 9.9999997473787516355514526367188e-05)) * half(_1023)) * half(_1023)), float3(65504.0))) * _1084), half3(float3(65504.0)))) + min(((_895 * min(_1505 * (_1505 * (half(6.283185482025146484375) * _1498)), half(65504.0))) * _930) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1287) * half(_1287)) / fast::max(_1273, 9.9999997473787516355514526367188e-05)) * half(_1306)) * half(_1306)), float3(65504.0))) * _1367), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1517, half(1.0)));
    return out;
}

