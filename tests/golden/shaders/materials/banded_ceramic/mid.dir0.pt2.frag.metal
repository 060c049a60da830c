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
    half3 _636 = normalize(half3(in.v_normal));
    float3 _652 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _777 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _885 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _777)), half(0.0), half(1.0));
    half3 _893 = half3((half(0.1599999964237213134765625) * _885) * _885);
    half _902 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _777)), half(0.08900000154972076416015625), half(1.0));
    half _845 = max(dot(_636, half3(_652)), half(9.9999997473787516355514526367188e-05));
    float4 _909 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, _902)), level(0.0));
    half3 _928 = half3(float3(1.0)) + (_893 * ((half(1.0) / half4(_909).y) - half(1.0)));
    float4 _938 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_652), _636)), level(_902 * (half(4.0) * (half(2.0) - _902))));
    float3 _983 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _986 = dot(_983, _983);
    float3 _991 = _983 * rsqrt(fast::max(_986, 9.9999999392252902907785028219223e-09));
    float _995 = _986 * float(frame.punctualLights[0].positionFalloff.w);
    float _1000 = fast::clamp(fma(-_995, _995, 1.0), 0.0, 1.0);
    float _1019 = fast::clamp(fma(dot(-_991, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1153 = _902 * _902;
    half3 _1164 = normalize(half3(_652) + half3(_991));
    half _1080 = clamp(dot(_636, half3(_991)), half(0.0), half(1.0));
    half3 _1191 = cross(_636, _1164);
    half _1194 = clamp(dot(_636, _1164), half(0.0), half(1.0)) * _1153;
    half _1211 = max(mix((half(2.0) * _1080) * _845, _1080 + _845, _1153), half(0.000244140625));
    half _1213 = half(1024.0) * _1153;
    half _1218 = _1213 / (fma(_1194, _1194, dot(_1191, _1191)) * (half(6433.98193359375) * _1211));
    float3 _1266 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1269 = dot(_1266, _1266);
    float3 _1274 = _1266 * rsqrt(fast::max(_1269, 9.9999999392252902907785028219223e-09));
    float _1278 = _1269 * float(frame.punctualLights[1].positionFalloff.w);
    float _1283 = fast::clamp(fma(-_1278, _1278, 1.0), 0.0, 1.0);
    float _1302 = fast::clamp(fma(dot(-_1274, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1447 = normalize(half3(_652) + half3(_1274));
    half _1363 = clamp(dot(_636, half3(_1274)), half(0.0), half(1.0));
    half3 _1474 = cross(_636, _1447);
    half _1477 = clamp(dot(_636, _1447), half(0.0), half(1.0)) * _1153;
    half _1494 = max(mix((half(2.0) * _1363) * _845, _1363 + _845, _1153), half(0.000244140625));
    half _1501 = _1213 / (fma(_1477, _1477, dot(_1474, _1474)) * (half(6433.98193359375) * _1494));
    half3 _1513 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_777))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_938).xyz * (mix(half4(_909).xxx, half4(_909).yyy, _893) * _928)) + min(((_893 * min(_1218 * (_1218 * (half(6.283185482025146484375) * _1211)), half(65504.0))) * _928) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1000) * half(_1000)) / fast::max(_986, 9.9999997473787516355514526367188e-05)) * half(_1019)) * half(_1019)), float3(65504.0))) * _1080), half3(float3(65504.0)))) + min(((_893 * min(_1501 * (_1501 * (half(6.283185482025146484375) * _1494)), half(65504.0))) * _928) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1283) * half(_1283)) / fast::max(_1269, 9.9999997473787516355514526367188e-05)) * half(_1302)) * half(_1302)), float3(65504.0))) * _1363), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1513, half(1.0)));
    return out;
}

