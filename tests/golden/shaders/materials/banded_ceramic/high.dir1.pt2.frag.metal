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
    half3 _683 = normalize(half3(in.v_normal));
    float3 _699 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _845 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _945 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _845)), half(0.0), half(1.0));
    half3 _953 = half3((half(0.1599999964237213134765625) * _945) * _945);
    half _962 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _845)), half(0.08900000154972076416015625), half(1.0));
    float4 _969 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_683, half3(_699)), half(9.9999997473787516355514526367188e-05)), _962)), level(0.0));
    float4 _988 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_699), _683)), level(_962 * (half(4.0) * (half(2.0) - _962))));
    half3 _736 = half4(frame.lightDirection).xyz;
    half _1139 = _962 * _962;
    half3 _1049 = half3(_699) + _736;
    half3 _1059 = _1049 * (half(64.0) * rsqrt(dot(_1049, _1049)));
    half _1068 = clamp(dot(_736, _1059) * half(0.015625), half(0.0), half(1.0));
    half4 _1287 = half4(cross(_683, _1059), _1139 * clamp(dot(_683, _1059), half(0.0), half(64.0)));
    half _1305 = fma(half(-0.3125), _1139, half(1.00820004940032958984375));
    half _1306 = (half(12.56637096405029296875) * max(_1068 * _1068, half(0.1500000059604644775390625))) * _1305;
    half _1311 = _1139 / ((dot(_1287, _1287) * half(0.000244140625)) * _1306);
    float3 _1358 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1361 = dot(_1358, _1358);
    float3 _1366 = _1358 * rsqrt(fast::max(_1361, 9.9999999392252902907785028219223e-09));
    float _1370 = _1361 * float(frame.punctualLights[0].positionFalloff.w);
    float _1375 = fast::clamp(fma(-_1370, _1370, 1.0), 0.0, 1.0);
    float _1394 = fast::clamp(fma(dot(-_1366, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1458 = half3(_699) + half3(_1366);
    half3 _1468 = _1458 * (half(64.0) * rsqrt(dot(_1458, _1458)));
    half _1477 = clamp(dot(half3(_1366), _1468) * half(0.015625), half(0.0), half(1.0));
    half4 _1696 = half4(cross(_683, _1468), _1139 * clamp(dot(_683, _1468), half(0.0), half(64.0)));
    half _1715 = (half(12.56637096405029296875) * max(_1477 * _1477, half(0.1500000059604644775390625))) * _1305;
    half _1720 = _1139 / ((dot(_1696, _1696) * half(0.000244140625)) * _1715);
    float3 _1767 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1770 = dot(_1767, _1767);
    float3 _1775 = _1767 * rsqrt(fast::max(_1770, 9.9999999392252902907785028219223e-09));
    float _1779 = _1770 * float(frame.punctualLights[1].positionFalloff.w);
    float _1784 = fast::clamp(fma(-_1779, _1779, 1.0), 0.0, 1.0);
    float _1803 = fast::clamp(fma(dot(-_1775, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1867 = half3(_699) + half3(_1775);
    half3 _1877 = _1867 * (half(64.0) * rsqrt(dot(_1867, _1867)));
    half _1886 = clamp(dot(half3(_1775), _1877) * half(0.015625), half(0.0), half(1.0));
    half4 _2105 = half4(cross(_683, _1877), _1139 * clamp(dot(_683, _1877), half(0.0), half(64.0)));
    half _2124 = (half(12.56637096405029296875) * max(_1886 * _1886, half(0.1500000059604644775390625))) * _1305;
    half _2129 = _1139 / ((dot(_2105, _2105) * half(0.000244140625)) * _2124);
    half3 _2140 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_845))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_988).xyz * mix(half4(_969).xxx, half4(_969).yyy, _953)) + min((_953 * half4(frame.lightColor).xyz) * (min((_1311 * _1311) * _1306, half(65504.0)) * clamp(dot(_683, _736), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_953 * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1375) * half(_1375)) / fast::max(_1361, 9.9999997473787516355514526367188e-05)) * half(_1394)) * half(_1394)), float3(65504.0)))) * (min((_1720 * _1720) * _1715, half(65504.0)) * clamp(dot(_683, half3(_1366)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_953 * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1784) * half(_1784)) / fast::max(_1770, 9.9999997473787516355514526367188e-05)) * half(_1803)) * half(_1803)), float3(65504.0)))) * (min((_2129 * _2129) * _2124, half(65504.0)) * clamp(dot(_683, half3(_1775)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2140, half(1.0)));
    return out;
}

