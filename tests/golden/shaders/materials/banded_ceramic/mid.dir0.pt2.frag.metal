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
    float _824 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _924 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _824)), half(0.0), half(1.0));
    half3 _932 = half3((half(0.1599999964237213134765625) * _924) * _924);
    half _941 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _824)), half(0.08900000154972076416015625), half(1.0));
    float4 _948 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_683, half3(_699)), half(9.9999997473787516355514526367188e-05)), _941)), level(0.0));
    float4 _967 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_699), _683)), level(_941 * (half(4.0) * (half(2.0) - _941))));
    float3 _1012 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1015 = dot(_1012, _1012);
    float3 _1020 = _1012 * rsqrt(fast::max(_1015, 9.9999999392252902907785028219223e-09));
    float _1024 = _1015 * float(frame.punctualLights[0].positionFalloff.w);
    float _1029 = fast::clamp(fma(-_1024, _1024, 1.0), 0.0, 1.0);
    float _1048 = fast::clamp(fma(dot(-_1020, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1202 = _941 * _941;
    half3 _1112 = half3(_699) + half3(_1020);
    half3 _1122 = _1112 * (half(64.0) * rsqrt(dot(_1112, _1112)));
    half _1131 = clamp(dot(half3(_1020), _1122) * half(0.015625), half(0.0), half(1.0));
    half4 _1350 = half4(cross(_683, _1122), _1202 * clamp(dot(_683, _1122), half(0.0), half(64.0)));
    half _1368 = fma(half(-0.3125), _1202, half(1.00820004940032958984375));
    half _1369 = (half(12.56637096405029296875) * max(_1131 * _1131, half(0.1500000059604644775390625))) * _1368;
    half _1374 = _1202 / ((dot(_1350, _1350) * half(0.000244140625)) * _1369);
    float3 _1421 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1424 = dot(_1421, _1421);
    float3 _1429 = _1421 * rsqrt(fast::max(_1424, 9.9999999392252902907785028219223e-09));
    float _1433 = _1424 * float(frame.punctualLights[1].positionFalloff.w);
    float _1438 = fast::clamp(fma(-_1433, _1433, 1.0), 0.0, 1.0);
    float _1457 = fast::clamp(fma(dot(-_1429, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1521 = half3(_699) + half3(_1429);
    half3 _1531 = _1521 * (half(64.0) * rsqrt(dot(_1521, _1521)));
    half _1540 = clamp(dot(half3(_1429), _1531) * half(0.015625), half(0.0), half(1.0));
    half4 _1759 = half4(cross(_683, _1531), _1202 * clamp(dot(_683, _1531), half(0.0), half(64.0)));
    half _1778 = (half(12.56637096405029296875) * max(_1540 * _1540, half(0.1500000059604644775390625))) * _1368;
    half _1783 = _1202 / ((dot(_1759, _1759) * half(0.000244140625)) * _1778);
    half3 _1794 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_824))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_967).xyz * mix(half4(_948).xxx, half4(_948).yyy, _932)) + min((_932 * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1029) * half(_1029)) / fast::max(_1015, 9.9999997473787516355514526367188e-05)) * half(_1048)) * half(_1048)), float3(65504.0)))) * (min((_1374 * _1374) * _1369, half(65504.0)) * clamp(dot(_683, half3(_1020)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_932 * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1438) * half(_1438)) / fast::max(_1424, 9.9999997473787516355514526367188e-05)) * half(_1457)) * half(_1457)), float3(65504.0)))) * (min((_1783 * _1783) * _1778, half(65504.0)) * clamp(dot(_683, half3(_1429)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1794, half(1.0)));
    return out;
}

