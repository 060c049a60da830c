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
    float3 _962 = in.v_tangent.xyz - (_831 * dot(_831, in.v_tangent.xyz));
    float _964 = _831.z;
    float3 _1661;
    if (abs(_964) < 0.5)
    {
        _1661 = float3(-_831.y, _831.x, 0.0);
    }
    else
    {
        _1661 = float3(0.0, -_964, _831.y);
    }
    float3 _991 = fast::normalize(select(_1661, _962, bool3(dot(_962, _962) > 0.001000000047497451305389404296875)));
    float _855 = fast::max(dot(_831, _835), 9.9999997473787516355514526367188e-05);
    float3 _1004 = cross(_831, _991);
    float _1055 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1050 = fast::clamp(float2(1.0 + _1055, 1.0 - _1055) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1010 = float2(1.0) / _1050;
    float2 _1012 = _1050 * 128.0;
    float3 _1675 = select(_1004, _991, bool3(_1055 >= 0.0));
    float _1284 = dot(_1675, _835);
    float _1291 = fast::min(abs(_1055) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1296 = fma(-_1291, 1.0 - _855, 1.0);
    float _1299 = _1291 * _1284;
    float4 _1339 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_855, params.facet_perceptualRoughness), level(0.0));
    float3 _1471 = fast::normalize(_835 + frame.lightDirection.xyz);
    float _1421 = fast::clamp(dot(_831, frame.lightDirection.xyz), 0.0, 1.0);
    float _1425 = fast::clamp(dot(_831, _1471), 0.0, 1.0);
    float2 _1488 = float2(dot(_991, _1471), dot(_1004, _1471)) * _1010;
    float _1496 = 1.0 / fma(_1425, _1425, dot(_1488, _1488));
    float _1535 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1471), 0.0, 1.0);
    float _1538 = _1535 * _1535;
    float3 _1568 = fma(facet_environment.sample(facet_environmentSmplr, ((((_831 * _1296) + (_1675 * _1299)) * (512.0 * fma(_1296, _855, _1299 * _1284))) - (_835 * (256.0 * fma(_1296, _1296, _1299 * _1299)))), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1339.xxx, _1339.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1339.y) - 1.0))), fast::min(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1538 * _1538) * _1535))) * ((((0.3183098733425140380859375 * (_1010.x * _1010.y)) * _1496) * _1496) * (64.0 / fma(_1421, length(float3(_1012 * float2(dot(_991, _835), dot(_1004, _835)), 128.0 * _855)), _855 * length(float3(_1012 * float2(dot(_991, frame.lightDirection.xyz), dot(_1004, frame.lightDirection.xyz)), 128.0 * _1421)))))) * (frame.lightColor.xyz * _1421), float3(65504.0)));
    out.fragColor = float4(_1568, 1.0);
    return out;
}

