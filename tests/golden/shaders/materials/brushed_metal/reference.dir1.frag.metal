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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _816 = fast::normalize(in.v_normal);
    float3 _820 = fast::normalize(in.v_toEye);
    float3 _948 = in.v_tangent.xyz - (_816 * dot(_816, in.v_tangent.xyz));
    float _950 = _816.z;
    float3 _1623;
    if (abs(_950) < 0.5)
    {
        _1623 = float3(-_816.y, _816.x, 0.0);
    }
    else
    {
        _1623 = float3(0.0, -_950, _816.y);
    }
    float3 _977 = fast::normalize(select(_1623, _948, bool3(dot(_948, _948) > 0.001000000047497451305389404296875)));
    float _840 = fast::max(dot(_816, _820), 9.9999997473787516355514526367188e-05);
    float3 _990 = cross(_816, _977);
    float2 _996 = float2(1.0) / params.facet_anisotropicAlpha;
    float2 _998 = params.facet_anisotropicAlpha * 128.0;
    float3 _1637 = select(_990, _977, bool3(params.facet_anisotropy >= 0.0));
    float _1253 = dot(_1637, _820);
    float _1260 = fma(-params.facet_anisotropicBend, 1.0 - _840, 1.0);
    float _1263 = params.facet_anisotropicBend * _1253;
    float4 _1302 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_840, params.facet_perceptualRoughness), level(0.0));
    float3 _1437 = fast::normalize(_820 + frame.lightDirection.xyz);
    float _1387 = fast::clamp(dot(_816, frame.lightDirection.xyz), 0.0, 1.0);
    float _1391 = fast::clamp(dot(_816, _1437), 0.0, 1.0);
    float2 _1454 = float2(dot(_977, _1437), dot(_990, _1437)) * _996;
    float _1462 = 1.0 / fma(_1391, _1391, dot(_1454, _1454));
    float _1501 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1437), 0.0, 1.0);
    float _1504 = _1501 * _1501;
    float3 _1534 = fma(facet_environment.sample(facet_environmentSmplr, ((((_816 * _1260) + (_1637 * _1263)) * (512.0 * fma(_1260, _840, _1263 * _1253))) - (_820 * (256.0 * fma(_1260, _1260, _1263 * _1263)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1302.xxx, _1302.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1302.y) - 1.0))), fast::min(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1504 * _1504) * _1501))) * ((((0.3183098733425140380859375 * (_996.x * _996.y)) * _1462) * _1462) * (64.0 / fma(_1387, length(float3(_998 * float2(dot(_977, _820), dot(_990, _820)), 128.0 * _840)), _840 * length(float3(_998 * float2(dot(_977, frame.lightDirection.xyz), dot(_990, frame.lightDirection.xyz)), 128.0 * _1387)))))) * (frame.lightColor.xyz * _1387), float3(65504.0)));
    out.fragColor = float4(_1534, 1.0);
    return out;
}

