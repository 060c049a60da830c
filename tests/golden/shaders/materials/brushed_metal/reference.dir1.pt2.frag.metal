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
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    float3 _914 = fast::normalize(in.v_normal);
    float3 _920 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1085 = in.v_tangent.xyz - (_914 * dot(_914, in.v_tangent.xyz));
    float _1087 = _914.z;
    float3 _2361;
    if (abs(_1087) < 0.5)
    {
        _2361 = float3(-_914.y, _914.x, 0.0);
    }
    else
    {
        _2361 = float3(0.0, -_1087, _914.y);
    }
    float3 _1114 = fast::normalize(select(_2361, _1085, bool3(dot(_1085, _1085) > 0.001000000047497451305389404296875)));
    float _940 = fast::max(dot(_914, _920), 9.9999997473787516355514526367188e-05);
    float3 _1127 = cross(_914, _1114);
    float2 _1133 = float2(1.0) / params.facet_anisotropicAlpha;
    float2 _1135 = params.facet_anisotropicAlpha * 128.0;
    float _1141 = 0.3183098733425140380859375 * (_1133.x * _1133.y);
    float _1157 = length(float3(_1135 * float2(dot(_1114, _920), dot(_1127, _920)), 128.0 * _940));
    float3 _2377 = select(_1127, _1114, bool3(params.facet_anisotropy >= 0.0));
    float _1390 = dot(_2377, _920);
    float _1397 = fma(-params.facet_anisotropicBend, 1.0 - _940, 1.0);
    float _1400 = params.facet_anisotropicBend * _1390;
    float4 _1439 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_940, params.facet_perceptualRoughness), level(0.0));
    float3 _1574 = fast::normalize(_920 + frame.lightDirection.xyz);
    float _1524 = fast::clamp(dot(_914, frame.lightDirection.xyz), 0.0, 1.0);
    float _1528 = fast::clamp(dot(_914, _1574), 0.0, 1.0);
    float2 _1591 = float2(dot(_1114, _1574), dot(_1127, _1574)) * _1133;
    float _1599 = 1.0 / fma(_1528, _1528, dot(_1591, _1591));
    float _1638 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1574), 0.0, 1.0);
    float _1641 = _1638 * _1638;
    float3 _1649 = float3(1.0) - float3(params.facet_f0);
    float3 _1706 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1709 = dot(_1706, _1706);
    float3 _1714 = _1706 * rsqrt(fast::max(_1709, 9.9999999392252902907785028219223e-09));
    float _1718 = _1709 * float(frame.punctualLights[0].positionFalloff.w);
    float _1723 = fast::clamp(fma(-_1718, _1718, 1.0), 0.0, 1.0);
    float _1742 = fast::clamp(fma(dot(-_1714, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1848 = fast::normalize(_920 + _1714);
    float _1798 = fast::clamp(dot(_914, _1714), 0.0, 1.0);
    float _1802 = fast::clamp(dot(_914, _1848), 0.0, 1.0);
    float2 _1865 = float2(dot(_1114, _1848), dot(_1127, _1848)) * _1133;
    float _1873 = 1.0 / fma(_1802, _1802, dot(_1865, _1865));
    float _1912 = 1.0 - fast::clamp(dot(_1714, _1848), 0.0, 1.0);
    float _1915 = _1912 * _1912;
    float3 _1945 = fma(facet_environment.sample(facet_environmentSmplr, ((((_914 * _1397) + (_2377 * _1400)) * (512.0 * fma(_1397, _940, _1400 * _1390))) - (_920 * (256.0 * fma(_1397, _1397, _1400 * _1400)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1439.xxx, _1439.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1439.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1649 * ((_1641 * _1641) * _1638))) * (((_1141 * _1599) * _1599) * (64.0 / fma(_1524, _1157, _940 * length(float3(_1135 * float2(dot(_1114, frame.lightDirection.xyz), dot(_1127, frame.lightDirection.xyz)), 128.0 * _1524)))))) * (frame.lightColor.xyz * _1524), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1649 * ((_1915 * _1915) * _1912))) * (((_1141 * _1873) * _1873) * (64.0 / fma(_1798, _1157, _940 * length(float3(_1135 * float2(dot(_1114, _1714), dot(_1127, _1714)), 128.0 * _1798)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1723 * _1723) / fast::max(_1709, 9.9999997473787516355514526367188e-05)) * _1742) * _1742)) * _1798), float3(65504.0));
    float3 _1980 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1983 = dot(_1980, _1980);
    float3 _1988 = _1980 * rsqrt(fast::max(_1983, 9.9999999392252902907785028219223e-09));
    float _1992 = _1983 * float(frame.punctualLights[1].positionFalloff.w);
    float _1997 = fast::clamp(fma(-_1992, _1992, 1.0), 0.0, 1.0);
    float _2016 = fast::clamp(fma(dot(-_1988, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2122 = fast::normalize(_920 + _1988);
    float _2072 = fast::clamp(dot(_914, _1988), 0.0, 1.0);
    float _2076 = fast::clamp(dot(_914, _2122), 0.0, 1.0);
    float2 _2139 = float2(dot(_1114, _2122), dot(_1127, _2122)) * _1133;
    float _2147 = 1.0 / fma(_2076, _2076, dot(_2139, _2139));
    float _2186 = 1.0 - fast::clamp(dot(_1988, _2122), 0.0, 1.0);
    float _2189 = _2186 * _2186;
    out.fragColor = float4(_1945 + fast::min(((float3(params.facet_f0) + (_1649 * ((_2189 * _2189) * _2186))) * (((_1141 * _2147) * _2147) * (64.0 / fma(_2072, _1157, _940 * length(float3(_1135 * float2(dot(_1114, _1988), dot(_1127, _1988)), 128.0 * _2072)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1997 * _1997) / fast::max(_1983, 9.9999997473787516355514526367188e-05)) * _2016) * _2016)) * _2072), float3(65504.0)), 1.0);
    return out;
}

