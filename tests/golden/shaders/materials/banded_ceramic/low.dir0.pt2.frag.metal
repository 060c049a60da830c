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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _616 = normalize(half3(in.v_normal));
    float3 _632 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _760 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _869 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _760)), half(0.0), half(1.0));
    half3 _877 = half3((half(0.1599999964237213134765625) * _869) * _869);
    half _886 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _760)), half(0.08900000154972076416015625), half(1.0));
    half3 _832 = reflect(-half3(_632), _616);
    float4 _893 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_616, half3(_632)), half(9.9999997473787516355514526367188e-05)), _886)), level(0.0));
    float4 _919 = facet_environment.sample(facet_environmentSmplr, float3(_832), level(_886 * half(4.0)));
    half3 _847 = mix(half4(_893).xxx, half4(_893).yyy, _877) * (half3(float3(1.0)) + (_877 * ((half(1.0) / half4(_893).y) - half(1.0))));
    float3 _964 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _967 = dot(_964, _964);
    float3 _972 = _964 * rsqrt(fast::max(_967, 9.9999999392252902907785028219223e-09));
    float _976 = _967 * float(frame.punctualLights[0].positionFalloff.w);
    float _981 = fast::clamp(fma(-_976, _976, 1.0), 0.0, 1.0);
    float _1000 = fast::clamp(fma(dot(-_972, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1167 = clamp(dot(_832, half3(_972)), half(0.0), half(1.0));
    half _1170 = _1167 * _1167;
    half4 _1639 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1170 * _1170, _886), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1182 = _1639.x;
    float3 _1227 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1230 = dot(_1227, _1227);
    float3 _1235 = _1227 * rsqrt(fast::max(_1230, 9.9999999392252902907785028219223e-09));
    float _1239 = _1230 * float(frame.punctualLights[1].positionFalloff.w);
    float _1244 = fast::clamp(fma(-_1239, _1239, 1.0), 0.0, 1.0);
    float _1263 = fast::clamp(fma(dot(-_1235, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1430 = clamp(dot(_832, half3(_1235)), half(0.0), half(1.0));
    half _1433 = _1430 * _1430;
    half4 _1664 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1433 * _1433, _886), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1445 = _1664.x;
    half3 _1454 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_760))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_919).xyz * _847) + min((_847 * ((_1182 * _1182) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_981) * half(_981)) / fast::max(_967, 9.9999997473787516355514526367188e-05)) * half(_1000)) * half(_1000)), float3(65504.0))) * clamp(dot(_616, half3(_972)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_847 * ((_1445 * _1445) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1244) * half(_1244)) / fast::max(_1230, 9.9999997473787516355514526367188e-05)) * half(_1263)) * half(_1263)), float3(65504.0))) * clamp(dot(_616, half3(_1235)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1454, half(1.0)));
    return out;
}

