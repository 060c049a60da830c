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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _831 = fast::normalize(in.v_normal);
    float3 _835 = fast::normalize(in.v_toEye);
    float3 _961 = in.v_tangent.xyz - (_831 * dot(_831, in.v_tangent.xyz));
    float _963 = _831.z;
    float3 _1660;
    if (abs(_963) < 0.5)
    {
        _1660 = float3(-_831.y, _831.x, 0.0);
    }
    else
    {
        _1660 = float3(0.0, -_963, _831.y);
    }
    float3 _990 = fast::normalize(select(_1660, _961, bool3(dot(_961, _961) > 0.001000000047497451305389404296875)));
    float _855 = fast::max(dot(_831, _835), 9.9999997473787516355514526367188e-05);
    float3 _1003 = cross(_831, _990);
    float _1054 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1049 = fast::clamp(float2(1.0 + _1054, 1.0 - _1054) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1009 = float2(1.0) / _1049;
    float2 _1011 = _1049 * 128.0;
    float3 _1674 = select(_1003, _990, bool3(_1054 >= 0.0));
    float _1283 = dot(_1674, _835);
    float _1290 = fast::min(abs(_1054) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1295 = fma(-_1290, 1.0 - _855, 1.0);
    float _1298 = _1290 * _1283;
    float4 _1338 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_855, params.facet_perceptualRoughness), level(0.0));
    float3 _1470 = fast::normalize(_835 + frame.lightDirection.xyz);
    float _1420 = fast::clamp(dot(_831, frame.lightDirection.xyz), 0.0, 1.0);
    float _1424 = fast::clamp(dot(_831, _1470), 0.0, 1.0);
    float2 _1487 = float2(dot(_990, _1470), dot(_1003, _1470)) * _1009;
    float _1495 = 1.0 / fma(_1424, _1424, dot(_1487, _1487));
    float _1534 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1470), 0.0, 1.0);
    float _1537 = _1534 * _1534;
    float3 _1567 = fma(facet_environment.sample(facet_environmentSmplr, ((((_831 * _1295) + (_1674 * _1298)) * (512.0 * fma(_1295, _855, _1298 * _1283))) - (_835 * (256.0 * fma(_1295, _1295, _1298 * _1298)))), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1338.xxx, _1338.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1338.y) - 1.0))), fast::min(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1537 * _1537) * _1534))) * ((((0.3183098733425140380859375 * (_1009.x * _1009.y)) * _1495) * _1495) * (64.0 / fma(_1420, length(float3(_1011 * float2(dot(_990, _835), dot(_1003, _835)), 128.0 * _855)), _855 * length(float3(_1011 * float2(dot(_990, frame.lightDirection.xyz), dot(_1003, frame.lightDirection.xyz)), 128.0 * _1420)))))) * (frame.lightColor.xyz * _1420), float3(65504.0)));
    out.fragColor = float4(_1567, 1.0);
    return out;
}

