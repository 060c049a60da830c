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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _801 = fast::normalize(in.v_normal);
    float3 _805 = fast::normalize(in.v_toEye);
    float3 _933 = in.v_tangent.xyz - (_801 * dot(_801, in.v_tangent.xyz));
    float _935 = _801.z;
    float3 _1598;
    if (abs(_935) < 0.5)
    {
        _1598 = float3(-_801.y, _801.x, 0.0);
    }
    else
    {
        _1598 = float3(0.0, -_935, _801.y);
    }
    float3 _962 = fast::normalize(select(_1598, _933, bool3(dot(_933, _933) > 0.001000000047497451305389404296875)));
    float _825 = fast::max(dot(_801, _805), 9.9999997473787516355514526367188e-05);
    float3 _975 = cross(_801, _962);
    float2 _981 = float2(1.0) / params.facet_anisotropicAlpha;
    float2 _983 = params.facet_anisotropicAlpha * 128.0;
    float3 _1612 = select(_975, _962, bool3(params.facet_anisotropy >= 0.0));
    float _1239 = dot(_1612, _805);
    float _1246 = fma(-params.facet_anisotropicBend, 1.0 - _825, 1.0);
    float _1249 = params.facet_anisotropicBend * _1239;
    float4 _1288 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_825, params.facet_perceptualRoughness), level(0.0));
    float _1359 = fast::clamp(dot(_801, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1412 = fast::normalize(_805 + frame.lightDirection.xyz);
    float _1366 = fast::clamp(dot(_801, _1412), 0.0, 1.0);
    float2 _1429 = float2(dot(_962, _1412), dot(_975, _1412)) * _981;
    float _1437 = 1.0 / fma(_1366, _1366, dot(_1429, _1429));
    float _1476 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1412), 0.0, 1.0);
    float _1479 = _1476 * _1476;
    float3 _1509 = fma(facet_environment.sample(facet_environmentSmplr, ((((_801 * _1246) + (_1612 * _1249)) * (512.0 * fma(_1246, _825, _1249 * _1239))) - (_805 * (256.0 * fma(_1246, _1246, _1249 * _1249)))), level(params.facet_environmentLod)).xyz, mix(_1288.xxx, _1288.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1288.y) - 1.0))), fast::min(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1479 * _1479) * _1476))) * ((((0.3183098733425140380859375 * (_981.x * _981.y)) * _1437) * _1437) * (64.0 / fma(_1359, length(float3(_983 * float2(dot(_962, _805), dot(_975, _805)), 128.0 * _825)), _825 * length(float3(_983 * float2(dot(_962, frame.lightDirection.xyz), dot(_975, frame.lightDirection.xyz)), 128.0 * _1359)))))) * (frame.lightColor.xyz * _1359), float3(65504.0)));
    out.fragColor = float4(_1509, 1.0);
    return out;
}

