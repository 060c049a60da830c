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
    half3 _1078 = half4(in.v_tangent).xyz;
    half3 _1085 = _1078 - (_937 * dot(_937, _1078));
    half _1087 = _937.z;
    half3 _2203;
    if (float(abs(_1087)) < 0.5)
    {
        _2203 = half3(-_937.y, _937.x, half(0.0));
    }
    else
    {
        _2203 = half3(half(0.0), -_1087, _937.y);
    }
    half3 _1114 = normalize(half3(select(float3(_2203), float3(_1085), bool3(float(dot(_1085, _1085)) > 0.001000000047497451305389404296875))));
    half _963 = max(dot(_937, half3(_943)), half(9.9999997473787516355514526367188e-05));
    half3 _1127 = cross(_937, _1114);
    half _1178 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1173 = clamp(half2(half(1.0) + _1178, half(1.0) - _1178) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1133 = half2(float2(1.0)) / _1173;
    half2 _1135 = _1173 * half(128.0);
    half _1141 = half(0.3183098733425140380859375) * (_1133.x * _1133.y);
    half _1157 = length(half3(_1135 * half2(dot(_1114, half3(_943)), dot(_1127, half3(_943))), half(128.0) * _963));
    half3 _2219 = select(_1127, _1114, bool3(float(_1178) >= 0.0));
    half _1407 = dot(_2219, half3(_943));
    half _1414 = min(abs(_1178) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1419 = fma(half(-float(_1414)), half(1.0) - _963, half(1.0));
    half _1422 = _1414 * _1407;
    float4 _1462 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_963, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1488 = facet_environment.sample(facet_environmentSmplr, float3(((((_937 * _1419) + (_2219 * _1422)) * (half(512.0) * fma(_1419, _963, _1422 * _1407))) - (half3(_943) * (half(256.0) * fma(_1419, _1419, _1422 * _1422))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1533 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1536 = dot(_1533, _1533);
    float3 _1541 = _1533 * rsqrt(fast::max(_1536, 9.9999999392252902907785028219223e-09));
    float _1545 = _1536 * float(frame.punctualLights[0].positionFalloff.w);
    float _1550 = fast::clamp(fma(-_1545, _1545, 1.0), 0.0, 1.0);
    float _1569 = fast::clamp(fma(dot(-_1541, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1679 = fast::normalize(_943 + _1541);
    half _1628 = clamp(dot(_937, half3(_1541)), half(0.0), half(1.0));
    half _1632 = clamp(dot(_937, half3(_1679)), half(0.0), half(1.0));
    half2 _1697 = half2(dot(_1114, half3(_1679)), dot(_1127, half3(_1679))) * _1133;
    half _1705 = half(1.0) / fma(_1632, _1632, dot(_1697, _1697));
    half _1746 = half(1.0) - clamp(dot(half3(_1541), half3(_1679)), half(0.0), half(1.0));
    half _1749 = _1746 * _1746;
    half3 _1757 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1660 = min(((half3(float3(params.facet_f0)) + (_1757 * ((_1749 * _1749) * _1746))) * min(((_1141 * _1705) * _1705) * min(half(64.0) / fma(_1628, _1157, _963 * length(half3(_1135 * half2(dot(_1114, half3(_1541)), dot(_1127, half3(_1541))), half(128.0) * _1628))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1550) * half(_1550)) / fast::max(_1536, 9.9999997473787516355514526367188e-05)) * half(_1569)) * half(_1569)), float3(65504.0))) * _1628), half3(float3(65504.0)));
    float3 _1815 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1818 = dot(_1815, _1815);
    float3 _1823 = _1815 * rsqrt(fast::max(_1818, 9.9999999392252902907785028219223e-09));
    float _1827 = _1818 * float(frame.punctualLights[1].positionFalloff.w);
    float _1832 = fast::clamp(fma(-_1827, _1827, 1.0), 0.0, 1.0);
    float _1851 = fast::clamp(fma(dot(-_1823, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1961 = fast::normalize(_943 + _1823);
    half _1910 = clamp(dot(_937, half3(_1823)), half(0.0), half(1.0));
    half _1914 = clamp(dot(_937, half3(_1961)), half(0.0), half(1.0));
    half2 _1979 = half2(dot(_1114, half3(_1961)), dot(_1127, half3(_1961))) * _1133;
    half _1987 = half(1.0) / fma(_1914, _1914, dot(_1979, _1979));
    half _2028 = half(1.0) - clamp(dot(half3(_1823), half3(_1961)), half(0.0), half(1.0));
    half _2031 = _2028 * _2028;
    half3 _1942 = min(((half3(float3(params.facet_f0)) + (_1757 * ((_2031 * _2031) * _2028))) * min(((_1141 * _1987) * _1987) * min(half(64.0) / fma(_1910, _1157, _963 * length(half3(_1135 * half2(dot(_1114, half3(_1823)), dot(_1127, half3(_1823))), half(128.0) * _1910))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1832) * half(_1832)) / fast::max(_1818, 9.9999997473787516355514526367188e-05)) * half(_1851)) * half(_1851)), float3(65504.0))) * _1910), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1488).xyz, mix(half4(_1462).xxx, half4(_1462).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1462).y) - half(1.0)))), _1660) + _1942, half(1.0)));
    return out;
}

