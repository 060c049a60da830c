#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _943 = normalize(half3(in.v_normal));
    float3 _949 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1084 = half4(in.v_tangent).xyz;
    half3 _1091 = _1084 - (_943 * dot(_943, _1084));
    half _1093 = _943.z;
    half3 _2214;
    if (float(abs(_1093)) < 0.5)
    {
        _2214 = half3(-_943.y, _943.x, half(0.0));
    }
    else
    {
        _2214 = half3(half(0.0), -_1093, _943.y);
    }
    half3 _1120 = normalize(half3(select(float3(_2214), float3(_1091), bool3(float(dot(_1091, _1091)) > 0.001000000047497451305389404296875))));
    half _969 = max(dot(_943, half3(_949)), half(9.9999997473787516355514526367188e-05));
    half3 _1133 = cross(_943, _1120);
    half _1184 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1179 = clamp(half2(half(1.0) + _1184, half(1.0) - _1184) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1139 = half2(float2(1.0)) / _1179;
    half2 _1141 = _1179 * half(128.0);
    half _1147 = half(0.3183098733425140380859375) * (_1139.x * _1139.y);
    half _1163 = length(half3(_1141 * half2(dot(_1120, half3(_949)), dot(_1133, half3(_949))), half(128.0) * _969));
    half3 _2230 = select(_1133, _1120, bool3(float(_1184) >= 0.0));
    half _1413 = dot(_2230, half3(_949));
    half _1420 = min(abs(_1184) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1425 = fma(half(-float(_1420)), half(1.0) - _969, half(1.0));
    half _1428 = _1420 * _1413;
    float4 _1468 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_969, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1499 = facet_environment.sample(facet_environmentSmplr, float3(((((_943 * _1425) + (_2230 * _1428)) * (half(512.0) * fma(_1425, _969, _1428 * _1413))) - (half3(_949) * (half(256.0) * fma(_1425, _1425, _1428 * _1428))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1544 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1547 = dot(_1544, _1544);
    float3 _1552 = _1544 * rsqrt(fast::max(_1547, 9.9999999392252902907785028219223e-09));
    float _1556 = _1547 * float(frame.punctualLights[0].positionFalloff.w);
    float _1561 = fast::clamp(fma(-_1556, _1556, 1.0), 0.0, 1.0);
    float _1580 = fast::clamp(fma(dot(-_1552, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1690 = fast::normalize(_949 + _1552);
    half _1639 = clamp(dot(_943, half3(_1552)), half(0.0), half(1.0));
    half _1643 = clamp(dot(_943, half3(_1690)), half(0.0), half(1.0));
    half2 _1708 = half2(dot(_1120, half3(_1690)), dot(_1133, half3(_1690))) * _1139;
    half _1716 = half(1.0) / fma(_1643, _1643, dot(_1708, _1708));
    half _1757 = half(1.0) - clamp(dot(half3(_1552), half3(_1690)), half(0.0), half(1.0));
    half _1760 = _1757 * _1757;
    half3 _1768 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1671 = min(((half3(float3(params.facet_f0)) + (_1768 * ((_1760 * _1760) * _1757))) * min(((_1147 * _1716) * _1716) * min(half(64.0) / fma(_1639, _1163, _969 * length(half3(_1141 * half2(dot(_1120, half3(_1552)), dot(_1133, half3(_1552))), half(128.0) * _1639))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1561) * half(_1561)) / fast::max(_1547, 9.9999997473787516355514526367188e-05)) * half(_1580)) * half(_1580)), float3(65504.0))) * _1639), half3(float3(65504.0)));
    float3 _1826 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1829 = dot(_1826, _1826);
    float3 _1834 = _1826 * rsqrt(fast::max(_1829, 9.9999999392252902907785028219223e-09));
    float _1838 = _1829 * float(frame.punctualLights[1].positionFalloff.w);
    float _1843 = fast::clamp(fma(-_1838, _1838, 1.0), 0.0, 1.0);
    float _1862 = fast::clamp(fma(dot(-_1834, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1972 = fast::normalize(_949 + _1834);
    half _1921 = clamp(dot(_943, half3(_1834)), half(0.0), half(1.0));
    half _1925 = clamp(dot(_943, half3(_1972)), half(0.0), half(1.0));
    half2 _1990 = half2(dot(_1120, half3(_1972)), dot(_1133, half3(_1972))) * _1139;
    half _1998 = half(1.0) / fma(_1925, _1925, dot(_1990, _1990));
    half _2039 = half(1.0) - clamp(dot(half3(_1834), half3(_1972)), half(0.0), half(1.0));
    half _2042 = _2039 * _2039;
    half3 _1953 = min(((half3(float3(params.facet_f0)) + (_1768 * ((_2042 * _2042) * _2039))) * min(((_1147 * _1998) * _1998) * min(half(64.0) / fma(_1921, _1163, _969 * length(half3(_1141 * half2(dot(_1120, half3(_1834)), dot(_1133, half3(_1834))), half(128.0) * _1921))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1843) * half(_1843)) / fast::max(_1829, 9.9999997473787516355514526367188e-05)) * half(_1862)) * half(_1862)), float3(65504.0))) * _1921), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1499).xyz, mix(half4(_1468).xxx, half4(_1468).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1468).y) - half(1.0)))), _1671) + _1953, half(1.0)));
    return out;
}

