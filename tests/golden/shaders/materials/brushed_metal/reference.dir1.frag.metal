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
    float3 _835 = fast::normalize(in.v_normal);
    float3 _839 = fast::normalize(in.v_toEye);
    float3 _965 = in.v_tangent.xyz - (_835 * dot(_835, in.v_tangent.xyz));
    float _967 = _835.z;
    float3 _1667;
    if (abs(_967) < 0.5)
    {
        _1667 = float3(-_835.y, _835.x, 0.0);
    }
    else
    {
        _1667 = float3(0.0, -_967, _835.y);
    }
    float3 _994 = fast::normalize(select(_1667, _965, bool3(dot(_965, _965) > 0.001000000047497451305389404296875)));
    float _859 = fast::max(dot(_835, _839), 9.9999997473787516355514526367188e-05);
    float3 _1007 = cross(_835, _994);
    float _1058 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1053 = fast::clamp(float2(1.0 + _1058, 1.0 - _1058) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1013 = float2(1.0) / _1053;
    float2 _1015 = _1053 * 128.0;
    float3 _1681 = select(_1007, _994, bool3(_1058 >= 0.0));
    float _1287 = dot(_1681, _839);
    float _1294 = fast::min(abs(_1058) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1299 = fma(-_1294, 1.0 - _859, 1.0);
    float _1302 = _1294 * _1287;
    float4 _1342 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_859, params.facet_perceptualRoughness), level(0.0));
    float3 _1477 = fast::normalize(_839 + frame.lightDirection.xyz);
    float _1427 = fast::clamp(dot(_835, frame.lightDirection.xyz), 0.0, 1.0);
    float _1431 = fast::clamp(dot(_835, _1477), 0.0, 1.0);
    float2 _1494 = float2(dot(_994, _1477), dot(_1007, _1477)) * _1013;
    float _1502 = 1.0 / fma(_1431, _1431, dot(_1494, _1494));
    float _1541 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1477), 0.0, 1.0);
    float _1544 = _1541 * _1541;
    float3 _1574 = fma(facet_environment.sample(facet_environmentSmplr, ((((_835 * _1299) + (_1681 * _1302)) * (512.0 * fma(_1299, _859, _1302 * _1287))) - (_839 * (256.0 * fma(_1299, _1299, _1302 * _1302)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1342.xxx, _1342.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1342.y) - 1.0))), fast::min(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1544 * _1544) * _1541))) * ((((0.3183098733425140380859375 * (_1013.x * _1013.y)) * _1502) * _1502) * (64.0 / fma(_1427, length(float3(_1015 * float2(dot(_994, _839), dot(_1007, _839)), 128.0 * _859)), _859 * length(float3(_1015 * float2(dot(_994, frame.lightDirection.xyz), dot(_1007, frame.lightDirection.xyz)), 128.0 * _1427)))))) * (frame.lightColor.xyz * _1427), float3(65504.0)));
    out.fragColor = float4(_1574, 1.0);
    return out;
}

