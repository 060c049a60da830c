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
    half3 _622 = normalize(half3(in.v_normal));
    float3 _638 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _766 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _875 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _766)), half(0.0), half(1.0));
    half3 _883 = half3((half(0.1599999964237213134765625) * _875) * _875);
    half _892 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _766)), half(0.08900000154972076416015625), half(1.0));
    half3 _838 = reflect(-half3(_638), _622);
    float4 _899 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_622, half3(_638)), half(9.9999997473787516355514526367188e-05)), _892)), level(0.0));
    float4 _930 = facet_environment.sample(facet_environmentSmplr, float3(_838), level(_892 * (half(4.0) * (half(2.0) - _892))));
    half3 _853 = mix(half4(_899).xxx, half4(_899).yyy, _883) * (half3(float3(1.0)) + (_883 * ((half(1.0) / half4(_899).y) - half(1.0))));
    float3 _975 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _978 = dot(_975, _975);
    float3 _983 = _975 * rsqrt(fast::max(_978, 9.9999999392252902907785028219223e-09));
    float _987 = _978 * float(frame.punctualLights[0].positionFalloff.w);
    float _992 = fast::clamp(fma(-_987, _987, 1.0), 0.0, 1.0);
    float _1011 = fast::clamp(fma(dot(-_983, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1178 = clamp(dot(_838, half3(_983)), half(0.0), half(1.0));
    half _1181 = _1178 * _1178;
    half4 _1651 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1181 * _1181, _892), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1193 = _1651.x;
    float3 _1238 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1241 = dot(_1238, _1238);
    float3 _1246 = _1238 * rsqrt(fast::max(_1241, 9.9999999392252902907785028219223e-09));
    float _1250 = _1241 * float(frame.punctualLights[1].positionFalloff.w);
    float _1255 = fast::clamp(fma(-_1250, _1250, 1.0), 0.0, 1.0);
    float _1274 = fast::clamp(fma(dot(-_1246, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1441 = clamp(dot(_838, half3(_1246)), half(0.0), half(1.0));
    half _1444 = _1441 * _1441;
    half4 _1676 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1444 * _1444, _892), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1456 = _1676.x;
    half3 _1465 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_766))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_930).xyz * _853) + min((_853 * ((_1193 * _1193) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_992) * half(_992)) / fast::max(_978, 9.9999997473787516355514526367188e-05)) * half(_1011)) * half(_1011)), float3(65504.0))) * clamp(dot(_622, half3(_983)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_853 * ((_1456 * _1456) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1255) * half(_1255)) / fast::max(_1241, 9.9999997473787516355514526367188e-05)) * half(_1274)) * half(_1274)), float3(65504.0))) * clamp(dot(_622, half3(_1246)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1465, half(1.0)));
    return out;
}

