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
    half3 _628 = normalize(half3(in.v_normal));
    float3 _644 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _769 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _869 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _769)), half(0.0), half(1.0));
    half3 _877 = half3((half(0.1599999964237213134765625) * _869) * _869);
    half _886 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _769)), half(0.08900000154972076416015625), half(1.0));
    half _835 = max(dot(_628, half3(_644)), half(9.9999997473787516355514526367188e-05));
    float4 _893 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_835, _886)), level(0.0));
    float4 _912 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_644), _628)), level(_886 * (half(4.0) * (half(2.0) - _886))));
    float3 _957 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _960 = dot(_957, _957);
    float3 _965 = _957 * rsqrt(fast::max(_960, 9.9999999392252902907785028219223e-09));
    float _969 = _960 * float(frame.punctualLights[0].positionFalloff.w);
    float _974 = fast::clamp(fma(-_969, _969, 1.0), 0.0, 1.0);
    float _993 = fast::clamp(fma(dot(-_965, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1124 = _886 * _886;
    half3 _1135 = normalize(half3(_644) + half3(_965));
    half _1054 = clamp(dot(_628, half3(_965)), half(0.0), half(1.0));
    half4 _1204 = half4(cross(_628, _1135), _1124 * clamp(dot(_628, _1135), half(0.0), half(1.0))) * half(64.0);
    half _1178 = half(4096.0) * _1124;
    half _1181 = half(6.283185482025146484375) * max(mix((half(2.0) * _1054) * _835, _1054 + _835, _1124), half(0.000244140625));
    half _1183 = _1178 / (dot(_1204, _1204) * _1181);
    float3 _1248 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1251 = dot(_1248, _1248);
    float3 _1256 = _1248 * rsqrt(fast::max(_1251, 9.9999999392252902907785028219223e-09));
    float _1260 = _1251 * float(frame.punctualLights[1].positionFalloff.w);
    float _1265 = fast::clamp(fma(-_1260, _1260, 1.0), 0.0, 1.0);
    float _1284 = fast::clamp(fma(dot(-_1256, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1426 = normalize(half3(_644) + half3(_1256));
    half _1345 = clamp(dot(_628, half3(_1256)), half(0.0), half(1.0));
    half4 _1495 = half4(cross(_628, _1426), _1124 * clamp(dot(_628, _1426), half(0.0), half(1.0))) * half(64.0);
    half _1472 = half(6.283185482025146484375) * max(mix((half(2.0) * _1345) * _835, _1345 + _835, _1124), half(0.000244140625));
    half _1474 = _1178 / (dot(_1495, _1495) * _1472);
    half3 _1503 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_769))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_912).xyz * mix(half4(_893).xxx, half4(_893).yyy, _877)) + min((_877 * min(_1183 * (_1183 * _1181), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_974) * half(_974)) / fast::max(_960, 9.9999997473787516355514526367188e-05)) * half(_993)) * half(_993)), float3(65504.0))) * _1054), half3(float3(65504.0)))) + min((_877 * min(_1474 * (_1474 * _1472), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1265) * half(_1265)) / fast::max(_1251, 9.9999997473787516355514526367188e-05)) * half(_1284)) * half(_1284)), float3(65504.0))) * _1345), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1503, half(1.0)));
    return out;
}

