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
    float _798 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _906 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _798)), half(0.0), half(1.0));
    half3 _914 = half3((half(0.1599999964237213134765625) * _906) * _906);
    half _923 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _798)), half(0.08900000154972076416015625), half(1.0));
    half _866 = max(dot(_636, half3(_652)), half(9.9999997473787516355514526367188e-05));
    float4 _930 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_866, _923)), level(0.0));
    half3 _949 = half3(float3(1.0)) + (_914 * ((half(1.0) / half4(_930).y) - half(1.0)));
    float4 _959 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_652), _636)), level(_923 * (half(4.0) * (half(2.0) - _923))));
    half3 _689 = half4(frame.lightDirection).xyz;
    half _1090 = _923 * _923;
    half3 _1101 = normalize(half3(_652) + _689);
    half _1017 = clamp(dot(_636, _689), half(0.0), half(1.0));
    half3 _1128 = cross(_636, _1101);
    half _1131 = clamp(dot(_636, _1101), half(0.0), half(1.0)) * _1090;
    half _1148 = max(mix((half(2.0) * _1017) * _866, _1017 + _866, _1090), half(0.000244140625));
    half _1150 = half(1024.0) * _1090;
    half _1155 = _1150 / (fma(_1131, _1131, dot(_1128, _1128)) * (half(6433.98193359375) * _1148));
    float3 _1203 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1206 = dot(_1203, _1203);
    float3 _1211 = _1203 * rsqrt(fast::max(_1206, 9.9999999392252902907785028219223e-09));
    float _1215 = _1206 * float(frame.punctualLights[0].positionFalloff.w);
    float _1220 = fast::clamp(fma(-_1215, _1215, 1.0), 0.0, 1.0);
    float _1239 = fast::clamp(fma(dot(-_1211, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1384 = normalize(half3(_652) + half3(_1211));
    half _1300 = clamp(dot(_636, half3(_1211)), half(0.0), half(1.0));
    half3 _1411 = cross(_636, _1384);
    half _1414 = clamp(dot(_636, _1384), half(0.0), half(1.0)) * _1090;
    half _1431 = max(mix((half(2.0) * _1300) * _866, _1300 + _866, _1090), half(0.000244140625));
    half _1438 = _1150 / (fma(_1414, _1414, dot(_1411, _1411)) * (half(6433.98193359375) * _1431));
    float3 _1486 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1489 = dot(_1486, _1486);
    float3 _1494 = _1486 * rsqrt(fast::max(_1489, 9.9999999392252902907785028219223e-09));
    float _1498 = _1489 * float(frame.punctualLights[1].positionFalloff.w);
    float _1503 = fast::clamp(fma(-_1498, _1498, 1.0), 0.0, 1.0);
    float _1522 = fast::clamp(fma(dot(-_1494, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1667 = normalize(half3(_652) + half3(_1494));
    half _1583 = clamp(dot(_636, half3(_1494)), half(0.0), half(1.0));
    half3 _1694 = cross(_636, _1667);
    half _1697 = clamp(dot(_636, _1667), half(0.0), half(1.0)) * _1090;
    half _1714 = max(mix((half(2.0) * _1583) * _866, _1583 + _866, _1090), half(0.000244140625));
    half _1721 = _1150 / (fma(_1697, _1697, dot(_1694, _1694)) * (half(6433.98193359375) * _1714));
    half3 _1733 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_798))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_959).xyz * (mix(half4(_930).xxx, half4(_930).yyy, _914) * _949)) + min(((_914 * min(_1155 * (_1155 * (half(6.283185482025146484375) * _1148)), half(65504.0))) * _949) * (half4(frame.lightColor).xyz * _1017), half3(float3(65504.0)))) + min(((_914 * min(_1438 * (_1438 * (half(6.283185482025146484375) * _1431)), half(65504.0))) * _949) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1220) * half(_1220)) / fast::max(_1206, 9.9999997473787516355514526367188e-05)) * half(_1239)) * half(_1239)), float3(65504.0))) * _1300), half3(float3(65504.0)))) + min(((_914 * min(_1721 * (_1721 * (half(6.283185482025146484375) * _1714)), half(65504.0))) * _949) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1503) * half(_1503)) / fast::max(_1489, 9.9999997473787516355514526367188e-05)) * half(_1522)) * half(_1522)), float3(65504.0))) * _1583), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1733, half(1.0)));
    return out;
}

