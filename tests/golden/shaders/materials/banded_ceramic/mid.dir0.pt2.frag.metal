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
    half3 _653 = normalize(half3(in.v_normal));
    float3 _669 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _794 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _902 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _794)), half(0.0), half(1.0));
    half3 _910 = half3((half(0.1599999964237213134765625) * _902) * _902);
    half _919 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _794)), half(0.08900000154972076416015625), half(1.0));
    half _862 = max(dot(_653, half3(_669)), half(9.9999997473787516355514526367188e-05));
    float4 _926 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_862, _919)), level(0.0));
    half3 _945 = half3(float3(1.0)) + (_910 * ((half(1.0) / half4(_926).y) - half(1.0)));
    float4 _952 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_669), _653)), level(_919 * half(4.0)));
    float3 _997 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1000 = dot(_997, _997);
    float3 _1005 = _997 * rsqrt(fast::max(_1000, 9.9999999392252902907785028219223e-09));
    float _1009 = _1000 * float(frame.punctualLights[0].positionFalloff.w);
    float _1014 = fast::clamp(fma(-_1009, _1009, 1.0), 0.0, 1.0);
    float _1033 = fast::clamp(fma(dot(-_1005, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1167 = _919 * _919;
    half3 _1178 = normalize(half3(_669) + half3(_1005));
    half _1094 = clamp(dot(_653, half3(_1005)), half(0.0), half(1.0));
    half3 _1241 = cross(_653, _1178) * half(64.0);
    half _1244 = half(64.0) * _1167;
    half _1245 = clamp(dot(_653, _1178), half(0.0), half(1.0)) * _1244;
    half _1221 = half(4096.0) * _1167;
    half _1224 = half(6.283185482025146484375) * max(mix((half(2.0) * _1094) * _862, _1094 + _862, _1167), half(0.000244140625));
    half _1226 = _1221 / (fma(_1245, _1245, dot(_1241, _1241)) * _1224);
    float3 _1293 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1296 = dot(_1293, _1293);
    float3 _1301 = _1293 * rsqrt(fast::max(_1296, 9.9999999392252902907785028219223e-09));
    float _1305 = _1296 * float(frame.punctualLights[1].positionFalloff.w);
    float _1310 = fast::clamp(fma(-_1305, _1305, 1.0), 0.0, 1.0);
    float _1329 = fast::clamp(fma(dot(-_1301, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1474 = normalize(half3(_669) + half3(_1301));
    half _1390 = clamp(dot(_653, half3(_1301)), half(0.0), half(1.0));
    half3 _1537 = cross(_653, _1474) * half(64.0);
    half _1541 = clamp(dot(_653, _1474), half(0.0), half(1.0)) * _1244;
    half _1520 = half(6.283185482025146484375) * max(mix((half(2.0) * _1390) * _862, _1390 + _862, _1167), half(0.000244140625));
    half _1522 = _1221 / (fma(_1541, _1541, dot(_1537, _1537)) * _1520);
    half3 _1553 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_794))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_952).xyz * (mix(half4(_926).xxx, half4(_926).yyy, _910) * _945)) + min(((_910 * min(_1226 * (_1226 * _1224), half(65504.0))) * _945) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1014) * half(_1014)) / fast::max(_1000, 9.9999997473787516355514526367188e-05)) * half(_1033)) * half(_1033)), float3(65504.0))) * _1094), half3(float3(65504.0)))) + min(((_910 * min(_1522 * (_1522 * _1520), half(65504.0))) * _945) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1310) * half(_1310)) / fast::max(_1296, 9.9999997473787516355514526367188e-05)) * half(_1329)) * half(_1329)), float3(65504.0))) * _1390), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1553, half(1.0)));
    return out;
}

