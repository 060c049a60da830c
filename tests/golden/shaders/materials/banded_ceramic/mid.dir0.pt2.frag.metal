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
    half3 _651 = normalize(half3(in.v_normal));
    float3 _667 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _792 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _900 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _792)), half(0.0), half(1.0));
    half3 _908 = half3((half(0.1599999964237213134765625) * _900) * _900);
    half _917 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _792)), half(0.08900000154972076416015625), half(1.0));
    half _860 = max(dot(_651, half3(_667)), half(9.9999997473787516355514526367188e-05));
    float4 _924 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_860, _917)), level(0.0));
    half3 _943 = half3(float3(1.0)) + (_908 * ((half(1.0) / half4(_924).y) - half(1.0)));
    float4 _950 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_667), _651)), level(_917 * half(4.0)));
    float3 _995 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _998 = dot(_995, _995);
    float3 _1003 = _995 * rsqrt(fast::max(_998, 9.9999999392252902907785028219223e-09));
    float _1007 = _998 * float(frame.punctualLights[0].positionFalloff.w);
    float _1012 = fast::clamp(fma(-_1007, _1007, 1.0), 0.0, 1.0);
    float _1031 = fast::clamp(fma(dot(-_1003, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1165 = _917 * _917;
    half3 _1176 = normalize(half3(_667) + half3(_1003));
    half _1092 = clamp(dot(_651, half3(_1003)), half(0.0), half(1.0));
    half4 _1245 = half4(cross(_651, _1176), _1165 * clamp(dot(_651, _1176), half(0.0), half(1.0))) * half(64.0);
    half _1219 = half(4096.0) * _1165;
    half _1222 = half(6.283185482025146484375) * max(mix((half(2.0) * _1092) * _860, _1092 + _860, _1165), half(0.000244140625));
    half _1224 = _1219 / (dot(_1245, _1245) * _1222);
    float3 _1289 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1292 = dot(_1289, _1289);
    float3 _1297 = _1289 * rsqrt(fast::max(_1292, 9.9999999392252902907785028219223e-09));
    float _1301 = _1292 * float(frame.punctualLights[1].positionFalloff.w);
    float _1306 = fast::clamp(fma(-_1301, _1301, 1.0), 0.0, 1.0);
    float _1325 = fast::clamp(fma(dot(-_1297, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1470 = normalize(half3(_667) + half3(_1297));
    half _1386 = clamp(dot(_651, half3(_1297)), half(0.0), half(1.0));
    half4 _1539 = half4(cross(_651, _1470), _1165 * clamp(dot(_651, _1470), half(0.0), half(1.0))) * half(64.0);
    half _1516 = half(6.283185482025146484375) * max(mix((half(2.0) * _1386) * _860, _1386 + _860, _1165), half(0.000244140625));
    half _1518 = _1219 / (dot(_1539, _1539) * _1516);
    half3 _1547 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_792))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_950).xyz * (mix(half4(_924).xxx, half4(_924).yyy, _908) * _943)) + min(((_908 * min(_1224 * (_1224 * _1222), half(65504.0))) * _943) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1012) * half(_1012)) / fast::max(_998, 9.9999997473787516355514526367188e-05)) * half(_1031)) * half(_1031)), float3(65504.0))) * _1092), half3(float3(65504.0)))) + min(((_908 * min(_1518 * (_1518 * _1516), half(65504.0))) * _943) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1306) * half(_1306)) / fast::max(_1292, 9.9999997473787516355514526367188e-05)) * half(_1325)) * half(_1325)), float3(65504.0))) * _1386), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1547, half(1.0)));
    return out;
}

