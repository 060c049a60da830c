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
    half3 _620 = normalize(half3(in.v_normal));
    float3 _636 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _764 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _873 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _764)), half(0.0), half(1.0));
    half3 _881 = half3((half(0.1599999964237213134765625) * _873) * _873);
    half _890 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _764)), half(0.08900000154972076416015625), half(1.0));
    half3 _836 = reflect(-half3(_636), _620);
    float4 _897 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_620, half3(_636)), half(9.9999997473787516355514526367188e-05)), _890)), level(0.0));
    float4 _926 = facet_environment.sample(facet_environmentSmplr, float3(_836), level(_890 * (half(4.0) * (half(2.0) - _890))));
    half3 _851 = mix(half4(_897).xxx, half4(_897).yyy, _881) * (half3(float3(1.0)) + (_881 * ((half(1.0) / half4(_897).y) - half(1.0))));
    float3 _971 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _974 = dot(_971, _971);
    float3 _979 = _971 * rsqrt(fast::max(_974, 9.9999999392252902907785028219223e-09));
    float _983 = _974 * float(frame.punctualLights[0].positionFalloff.w);
    float _988 = fast::clamp(fma(-_983, _983, 1.0), 0.0, 1.0);
    float _1007 = fast::clamp(fma(dot(-_979, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1174 = clamp(dot(_836, half3(_979)), half(0.0), half(1.0));
    half _1177 = _1174 * _1174;
    half4 _1647 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1177 * _1177, _890), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1189 = _1647.x;
    float3 _1234 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1237 = dot(_1234, _1234);
    float3 _1242 = _1234 * rsqrt(fast::max(_1237, 9.9999999392252902907785028219223e-09));
    float _1246 = _1237 * float(frame.punctualLights[1].positionFalloff.w);
    float _1251 = fast::clamp(fma(-_1246, _1246, 1.0), 0.0, 1.0);
    float _1270 = fast::clamp(fma(dot(-_1242, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1437 = clamp(dot(_836, half3(_1242)), half(0.0), half(1.0));
    half _1440 = _1437 * _1437;
    half4 _1672 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1440 * _1440, _890), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1452 = _1672.x;
    half3 _1461 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_764))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_926).xyz * _851) + min((_851 * ((_1189 * _1189) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_988) * half(_988)) / fast::max(_974, 9.9999997473787516355514526367188e-05)) * half(_1007)) * half(_1007)), float3(65504.0))) * clamp(dot(_620, half3(_979)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_851 * ((_1452 * _1452) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1251) * half(_1251)) / fast::max(_1237, 9.9999997473787516355514526367188e-05)) * half(_1270)) * half(_1270)), float3(65504.0))) * clamp(dot(_620, half3(_1242)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1461, half(1.0)));
    return out;
}

