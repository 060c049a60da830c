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
    float3 _837 = fast::normalize(in.v_normal);
    float3 _841 = fast::normalize(in.v_toEye);
    float3 _967 = in.v_tangent.xyz - (_837 * dot(_837, in.v_tangent.xyz));
    float _969 = _837.z;
    float3 _1671;
    if (abs(_969) < 0.5)
    {
        _1671 = float3(-_837.y, _837.x, 0.0);
    }
    else
    {
        _1671 = float3(0.0, -_969, _837.y);
    }
    float3 _996 = fast::normalize(select(_1671, _967, bool3(dot(_967, _967) > 0.001000000047497451305389404296875)));
    float _861 = fast::max(dot(_837, _841), 9.9999997473787516355514526367188e-05);
    float3 _1009 = cross(_837, _996);
    float _1060 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1055 = fast::clamp(float2(1.0 + _1060, 1.0 - _1060) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1015 = float2(1.0) / _1055;
    float2 _1017 = _1055 * 128.0;
    float3 _1685 = select(_1009, _996, bool3(_1060 >= 0.0));
    float _1289 = dot(_1685, _841);
    float _1296 = fast::min(abs(_1060) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1301 = fma(-_1296, 1.0 - _861, 1.0);
    float _1304 = _1296 * _1289;
    float4 _1344 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_861, params.facet_perceptualRoughness), level(0.0));
    float3 _1481 = fast::normalize(_841 + frame.lightDirection.xyz);
    float _1431 = fast::clamp(dot(_837, frame.lightDirection.xyz), 0.0, 1.0);
    float _1435 = fast::clamp(dot(_837, _1481), 0.0, 1.0);
    float2 _1498 = float2(dot(_996, _1481), dot(_1009, _1481)) * _1015;
    float _1506 = 1.0 / fma(_1435, _1435, dot(_1498, _1498));
    float _1545 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1481), 0.0, 1.0);
    float _1548 = _1545 * _1545;
    float3 _1578 = fma(facet_environment.sample(facet_environmentSmplr, ((((_837 * _1301) + (_1685 * _1304)) * (512.0 * fma(_1301, _861, _1304 * _1289))) - (_841 * (256.0 * fma(_1301, _1301, _1304 * _1304)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1344.xxx, _1344.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1344.y) - 1.0))), fast::min(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1548 * _1548) * _1545))) * ((((0.3183098733425140380859375 * (_1015.x * _1015.y)) * _1506) * _1506) * (64.0 / fma(_1431, length(float3(_1017 * float2(dot(_996, _841), dot(_1009, _841)), 128.0 * _861)), _861 * length(float3(_1017 * float2(dot(_996, frame.lightDirection.xyz), dot(_1009, frame.lightDirection.xyz)), 128.0 * _1431)))))) * (frame.lightColor.xyz * _1431), float3(65504.0)));
    out.fragColor = float4(_1578, 1.0);
    return out;
}

