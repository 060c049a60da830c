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
    half3 _937 = normalize(half3(in.v_normal));
    float3 _943 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1099 = half4(in.v_tangent).xyz;
    half3 _1106 = _1099 - (_937 * dot(_937, _1099));
    half _1108 = _937.z;
    half3 _2426;
    if (float(abs(_1108)) < 0.5)
    {
        _2426 = half3(-_937.y, _937.x, half(0.0));
    }
    else
    {
        _2426 = half3(half(0.0), -_1108, _937.y);
    }
    half3 _1135 = normalize(half3(select(float3(_2426), float3(_1106), bool3(float(dot(_1106, _1106)) > 0.001000000047497451305389404296875))));
    half _963 = max(dot(_937, half3(_943)), half(9.9999997473787516355514526367188e-05));
    half3 _1148 = cross(_937, _1135);
    half _1199 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1194 = clamp(half2(half(1.0) + _1199, half(1.0) - _1199) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1154 = half2(float2(1.0)) / _1194;
    half2 _1156 = _1194 * half(128.0);
    half _1162 = half(0.3183098733425140380859375) * (_1154.x * _1154.y);
    half _1178 = length(half3(_1156 * half2(dot(_1135, half3(_943)), dot(_1148, half3(_943))), half(128.0) * _963));
    half3 _2442 = select(_1148, _1135, bool3(float(_1199) >= 0.0));
    half _1428 = dot(_2442, half3(_943));
    half _1435 = min(abs(_1199) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1440 = fma(half(-float(_1435)), half(1.0) - _963, half(1.0));
    half _1443 = _1435 * _1428;
    float4 _1483 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_963, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1509 = facet_environment.sample(facet_environmentSmplr, float3(((((_937 * _1440) + (_2442 * _1443)) * (half(512.0) * fma(_1440, _963, _1443 * _1428))) - (half3(_943) * (half(256.0) * fma(_1440, _1440, _1443 * _1443))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1616 = fast::normalize(_943 + frame.lightDirection.xyz);
    half _1565 = clamp(dot(_937, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1569 = clamp(dot(_937, half3(_1616)), half(0.0), half(1.0));
    half2 _1634 = half2(dot(_1135, half3(_1616)), dot(_1148, half3(_1616))) * _1154;
    half _1642 = half(1.0) / fma(_1569, _1569, dot(_1634, _1634));
    half _1683 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1616)), half(0.0), half(1.0));
    half _1686 = _1683 * _1683;
    half3 _1694 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1752 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1755 = dot(_1752, _1752);
    float3 _1760 = _1752 * rsqrt(fast::max(_1755, 9.9999999392252902907785028219223e-09));
    float _1764 = _1755 * float(frame.punctualLights[0].positionFalloff.w);
    float _1769 = fast::clamp(fma(-_1764, _1764, 1.0), 0.0, 1.0);
    float _1788 = fast::clamp(fma(dot(-_1760, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1898 = fast::normalize(_943 + _1760);
    half _1847 = clamp(dot(_937, half3(_1760)), half(0.0), half(1.0));
    half _1851 = clamp(dot(_937, half3(_1898)), half(0.0), half(1.0));
    half2 _1916 = half2(dot(_1135, half3(_1898)), dot(_1148, half3(_1898))) * _1154;
    half _1924 = half(1.0) / fma(_1851, _1851, dot(_1916, _1916));
    half _1965 = half(1.0) - clamp(dot(half3(_1760), half3(_1898)), half(0.0), half(1.0));
    half _1968 = _1965 * _1965;
    half3 _1879 = min(((half3(float3(params.facet_f0)) + (_1694 * ((_1968 * _1968) * _1965))) * min(((_1162 * _1924) * _1924) * min(half(64.0) / fma(_1847, _1178, _963 * length(half3(_1156 * half2(dot(_1135, half3(_1760)), dot(_1148, half3(_1760))), half(128.0) * _1847))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1769) * half(_1769)) / fast::max(_1755, 9.9999997473787516355514526367188e-05)) * half(_1788)) * half(_1788)), float3(65504.0))) * _1847), half3(float3(65504.0)));
    half3 _1998 = fma(half4(_1509).xyz, mix(half4(_1483).xxx, half4(_1483).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1483).y) - half(1.0)))), min(((half3(float3(params.facet_f0)) + (_1694 * ((_1686 * _1686) * _1683))) * min(((_1162 * _1642) * _1642) * min(half(64.0) / fma(_1565, _1178, _963 * length(half3(_1156 * half2(dot(_1135, half3(frame.lightDirection.xyz)), dot(_1148, half3(frame.lightDirection.xyz))), half(128.0) * _1565))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1565), half3(float3(65504.0)))) + _1879;
    float3 _2034 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2037 = dot(_2034, _2034);
    float3 _2042 = _2034 * rsqrt(fast::max(_2037, 9.9999999392252902907785028219223e-09));
    float _2046 = _2037 * float(frame.punctualLights[1].positionFalloff.w);
    float _2051 = fast::clamp(fma(-_2046, _2046, 1.0), 0.0, 1.0);
    float _2070 = fast::clamp(fma(dot(-_2042, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2180 = fast::normalize(_943 + _2042);
    half _2129 = clamp(dot(_937, half3(_2042)), half(0.0), half(1.0));
    half _2133 = clamp(dot(_937, half3(_2180)), half(0.0), half(1.0));
    half2 _2198 = half2(dot(_1135, half3(_2180)), dot(_1148, half3(_2180))) * _1154;
    half _2206 = half(1.0) / fma(_2133, _2133, dot(_2198, _2198));
    half _2247 = half(1.0) - clamp(dot(half3(_2042), half3(_2180)), half(0.0), half(1.0));
    half _2250 = _2247 * _2247;
    half3 _2161 = min(((half3(float3(params.facet_f0)) + (_1694 * ((_2250 * _2250) * _2247))) * min(((_1162 * _2206) * _2206) * min(half(64.0) / fma(_2129, _1178, _963 * length(half3(_1156 * half2(dot(_1135, half3(_2042)), dot(_1148, half3(_2042))), half(128.0) * _2129))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2051) * half(_2051)) / fast::max(_2037, 9.9999997473787516355514526367188e-05)) * half(_2070)) * half(_2070)), float3(65504.0))) * _2129), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1998 + _2161, half(1.0)));
    return out;
}

