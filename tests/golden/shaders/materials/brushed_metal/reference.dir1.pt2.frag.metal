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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _899 = fast::normalize(in.v_normal);
    float3 _905 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1070 = in.v_tangent.xyz - (_899 * dot(_899, in.v_tangent.xyz));
    float _1072 = _899.z;
    float3 _2336;
    if (abs(_1072) < 0.5)
    {
        _2336 = float3(-_899.y, _899.x, 0.0);
    }
    else
    {
        _2336 = float3(0.0, -_1072, _899.y);
    }
    float3 _1099 = fast::normalize(select(_2336, _1070, bool3(dot(_1070, _1070) > 0.001000000047497451305389404296875)));
    float _925 = fast::max(dot(_899, _905), 9.9999997473787516355514526367188e-05);
    float3 _1112 = cross(_899, _1099);
    float2 _1118 = float2(1.0) / params.facet_anisotropicAlpha;
    float2 _1120 = params.facet_anisotropicAlpha * 128.0;
    float _1126 = 0.3183098733425140380859375 * (_1118.x * _1118.y);
    float _1142 = length(float3(_1120 * float2(dot(_1099, _905), dot(_1112, _905)), 128.0 * _925));
    float3 _2352 = select(_1112, _1099, bool3(params.facet_anisotropy >= 0.0));
    float _1376 = dot(_2352, _905);
    float _1383 = fma(-params.facet_anisotropicBend, 1.0 - _925, 1.0);
    float _1386 = params.facet_anisotropicBend * _1376;
    float4 _1425 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_925, params.facet_perceptualRoughness), level(0.0));
    float _1496 = fast::clamp(dot(_899, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1549 = fast::normalize(_905 + frame.lightDirection.xyz);
    float _1503 = fast::clamp(dot(_899, _1549), 0.0, 1.0);
    float2 _1566 = float2(dot(_1099, _1549), dot(_1112, _1549)) * _1118;
    float _1574 = 1.0 / fma(_1503, _1503, dot(_1566, _1566));
    float _1613 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1549), 0.0, 1.0);
    float _1616 = _1613 * _1613;
    float3 _1624 = float3(1.0) - float3(params.facet_f0);
    float3 _1681 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1684 = dot(_1681, _1681);
    float3 _1689 = _1681 * rsqrt(fast::max(_1684, 9.9999999392252902907785028219223e-09));
    float _1693 = _1684 * float(frame.punctualLights[0].positionFalloff.w);
    float _1698 = fast::clamp(fma(-_1693, _1693, 1.0), 0.0, 1.0);
    float _1717 = fast::clamp(fma(dot(-_1689, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1770 = fast::clamp(dot(_899, _1689), 0.0, 1.0);
    float3 _1823 = fast::normalize(_905 + _1689);
    float _1777 = fast::clamp(dot(_899, _1823), 0.0, 1.0);
    float2 _1840 = float2(dot(_1099, _1823), dot(_1112, _1823)) * _1118;
    float _1848 = 1.0 / fma(_1777, _1777, dot(_1840, _1840));
    float _1887 = 1.0 - fast::clamp(dot(_1689, _1823), 0.0, 1.0);
    float _1890 = _1887 * _1887;
    float3 _1920 = fma(facet_environment.sample(facet_environmentSmplr, ((((_899 * _1383) + (_2352 * _1386)) * (512.0 * fma(_1383, _925, _1386 * _1376))) - (_905 * (256.0 * fma(_1383, _1383, _1386 * _1386)))), level(params.facet_environmentLod)).xyz, mix(_1425.xxx, _1425.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1425.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1624 * ((_1616 * _1616) * _1613))) * (((_1126 * _1574) * _1574) * (64.0 / fma(_1496, _1142, _925 * length(float3(_1120 * float2(dot(_1099, frame.lightDirection.xyz), dot(_1112, frame.lightDirection.xyz)), 128.0 * _1496)))))) * (frame.lightColor.xyz * _1496), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1624 * ((_1890 * _1890) * _1887))) * (((_1126 * _1848) * _1848) * (64.0 / fma(_1770, _1142, _925 * length(float3(_1120 * float2(dot(_1099, _1689), dot(_1112, _1689)), 128.0 * _1770)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1698 * _1698) / fast::max(_1684, 9.9999997473787516355514526367188e-05)) * _1717) * _1717)) * _1770), float3(65504.0));
    float3 _1955 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1958 = dot(_1955, _1955);
    float3 _1963 = _1955 * rsqrt(fast::max(_1958, 9.9999999392252902907785028219223e-09));
    float _1967 = _1958 * float(frame.punctualLights[1].positionFalloff.w);
    float _1972 = fast::clamp(fma(-_1967, _1967, 1.0), 0.0, 1.0);
    float _1991 = fast::clamp(fma(dot(-_1963, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _2044 = fast::clamp(dot(_899, _1963), 0.0, 1.0);
    float3 _2097 = fast::normalize(_905 + _1963);
    float _2051 = fast::clamp(dot(_899, _2097), 0.0, 1.0);
    float2 _2114 = float2(dot(_1099, _2097), dot(_1112, _2097)) * _1118;
    float _2122 = 1.0 / fma(_2051, _2051, dot(_2114, _2114));
    float _2161 = 1.0 - fast::clamp(dot(_1963, _2097), 0.0, 1.0);
    float _2164 = _2161 * _2161;
    out.fragColor = float4(_1920 + fast::min(((float3(params.facet_f0) + (_1624 * ((_2164 * _2164) * _2161))) * (((_1126 * _2122) * _2122) * (64.0 / fma(_2044, _1142, _925 * length(float3(_1120 * float2(dot(_1099, _1963), dot(_1112, _1963)), 128.0 * _2044)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1972 * _1972) / fast::max(_1958, 9.9999997473787516355514526367188e-05)) * _1991) * _1991)) * _2044), float3(65504.0)), 1.0);
    return out;
}

