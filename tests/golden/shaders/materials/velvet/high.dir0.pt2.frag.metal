#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
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
    half3 _673 = normalize(half3(in.v_normal));
    float3 _679 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _817 = _673.y;
    half _822 = _673.z;
    half _827 = _673.x;
    half3 _895 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _817)) + (half4(frame.sh[2]).xyz * _822)) + (half4(frame.sh[3]).xyz * _827)) + (((((half4(frame.sh[4]).xyz * (_827 * _817)) + (half4(frame.sh[5]).xyz * (_817 * _822))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _822, _822, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_827 * _822))) + (half4(frame.sh[8]).xyz * fma(_827, _827, half(-float(_817 * _817))))), half3(float3(0.0)));
    half _936 = max(dot(_673, half3(_679)), half(9.9999997473787516355514526367188e-05));
    float4 _941 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_936, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _995 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1649 = half4(_941);
    half _954 = _1649.z;
    half _956 = fma(half(-float(max(_995.x, max(_995.y, _995.z)))), _954, half(1.0));
    half4 _1653 = half4(_941);
    half _961 = _1653.w;
    float4 _1011 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_679), _673)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1048 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1051 = dot(_1048, _1048);
    float3 _1056 = _1048 * rsqrt(fast::max(_1051, 9.9999999392252902907785028219223e-09));
    float _1060 = _1051 * float(frame.punctualLights[0].positionFalloff.w);
    float _1065 = fast::clamp(fma(-_1060, _1060, 1.0), 0.0, 1.0);
    float _1084 = fast::clamp(fma(dot(-_1056, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1118 = dot(_673, half3(_1056));
    half _1120 = clamp(_1118, half(0.0), half(1.0));
    half _1132 = clamp(dot(_673, half3(fast::normalize(_679 + _1056))), half(0.0), half(1.0));
    half _1203 = half(8192.0) * fma(half(-float(_1120)), _936, _1120 + _936);
    half _1207 = half(1.0) / (half(params.facet_alpha) * _1203);
    half _1214 = half(2048.0) * half(params.facet_alpha);
    half3 _1165 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1118 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1120), half3(float3(0.0)), half3(float3(1.0)))) * _956) + (_995 * ((((fma(_1207, _1203, half(2.0)) * pow(max(fma(half(-float(_1132)), _1132, half(1.0)), half(0.0)), half(0.5) * (_1207 * _1203))) * half(0.15915493667125701904296875)) * (_1120 * (_1207 * _1214))) * _961))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1065) * half(_1065)) / fast::max(_1051, 9.9999997473787516355514526367188e-05)) * half(_1084)) * half(_1084)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1278 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1281 = dot(_1278, _1278);
    float3 _1286 = _1278 * rsqrt(fast::max(_1281, 9.9999999392252902907785028219223e-09));
    float _1290 = _1281 * float(frame.punctualLights[1].positionFalloff.w);
    float _1295 = fast::clamp(fma(-_1290, _1290, 1.0), 0.0, 1.0);
    float _1314 = fast::clamp(fma(dot(-_1286, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1348 = dot(_673, half3(_1286));
    half _1350 = clamp(_1348, half(0.0), half(1.0));
    half _1362 = clamp(dot(_673, half3(fast::normalize(_679 + _1286))), half(0.0), half(1.0));
    half _1433 = half(8192.0) * fma(half(-float(_1350)), _936, _1350 + _936);
    half _1437 = half(1.0) / (half(params.facet_alpha) * _1433);
    half3 _1395 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1348 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1350), half3(float3(0.0)), half3(float3(1.0)))) * _956) + (_995 * ((((fma(_1437, _1433, half(2.0)) * pow(max(fma(half(-float(_1362)), _1362, half(1.0)), half(0.0)), half(0.5) * (_1437 * _1433))) * half(0.15915493667125701904296875)) * (_1350 * (_1437 * _1214))) * _961))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1295) * half(_1295)) / fast::max(_1281, 9.9999997473787516355514526367188e-05)) * half(_1314)) * half(_1314)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1011).xyz, _995 * _954, (half3(float3(params.facet_diffuseColor)) * _895) * _956) + _1165) + _1395, half(1.0)));
    return out;
}

