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
    float3 _935 = fast::normalize(in.v_normal);
    float3 _941 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1104 = in.v_tangent.xyz - (_935 * dot(_935, in.v_tangent.xyz));
    float _1106 = _935.z;
    float3 _2409;
    if (abs(_1106) < 0.5)
    {
        _2409 = float3(-_935.y, _935.x, 0.0);
    }
    else
    {
        _2409 = float3(0.0, -_1106, _935.y);
    }
    float3 _1133 = fast::normalize(select(_2409, _1104, bool3(dot(_1104, _1104) > 0.001000000047497451305389404296875)));
    float _961 = fast::max(dot(_935, _941), 9.9999997473787516355514526367188e-05);
    float3 _1146 = cross(_935, _1133);
    float _1197 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1192 = fast::clamp(float2(1.0 + _1197, 1.0 - _1197) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1152 = float2(1.0) / _1192;
    float2 _1154 = _1192 * 128.0;
    float _1160 = 0.3183098733425140380859375 * (_1152.x * _1152.y);
    float _1176 = length(float3(_1154 * float2(dot(_1133, _941), dot(_1146, _941)), 128.0 * _961));
    float3 _2425 = select(_1146, _1133, bool3(_1197 >= 0.0));
    float _1426 = dot(_2425, _941);
    float _1433 = fast::min(abs(_1197) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1438 = fma(-_1433, 1.0 - _961, 1.0);
    float _1441 = _1433 * _1426;
    float4 _1481 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_961, params.facet_perceptualRoughness), level(0.0));
    float3 _1618 = fast::normalize(_941 + frame.lightDirection.xyz);
    float _1568 = fast::clamp(dot(_935, frame.lightDirection.xyz), 0.0, 1.0);
    float _1572 = fast::clamp(dot(_935, _1618), 0.0, 1.0);
    float2 _1635 = float2(dot(_1133, _1618), dot(_1146, _1618)) * _1152;
    float _1643 = 1.0 / fma(_1572, _1572, dot(_1635, _1635));
    float _1682 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1618), 0.0, 1.0);
    float _1685 = _1682 * _1682;
    float3 _1693 = float3(1.0) - float3(params.facet_f0);
    float3 _1750 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1753 = dot(_1750, _1750);
    float3 _1758 = _1750 * rsqrt(fast::max(_1753, 9.9999999392252902907785028219223e-09));
    float _1762 = _1753 * float(frame.punctualLights[0].positionFalloff.w);
    float _1767 = fast::clamp(fma(-_1762, _1762, 1.0), 0.0, 1.0);
    float _1786 = fast::clamp(fma(dot(-_1758, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1892 = fast::normalize(_941 + _1758);
    float _1842 = fast::clamp(dot(_935, _1758), 0.0, 1.0);
    float _1846 = fast::clamp(dot(_935, _1892), 0.0, 1.0);
    float2 _1909 = float2(dot(_1133, _1892), dot(_1146, _1892)) * _1152;
    float _1917 = 1.0 / fma(_1846, _1846, dot(_1909, _1909));
    float _1956 = 1.0 - fast::clamp(dot(_1758, _1892), 0.0, 1.0);
    float _1959 = _1956 * _1956;
    float3 _1989 = fma(facet_environment.sample(facet_environmentSmplr, ((((_935 * _1438) + (_2425 * _1441)) * (512.0 * fma(_1438, _961, _1441 * _1426))) - (_941 * (256.0 * fma(_1438, _1438, _1441 * _1441)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1481.xxx, _1481.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1481.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1693 * ((_1685 * _1685) * _1682))) * (((_1160 * _1643) * _1643) * (64.0 / fma(_1568, _1176, _961 * length(float3(_1154 * float2(dot(_1133, frame.lightDirection.xyz), dot(_1146, frame.lightDirection.xyz)), 128.0 * _1568)))))) * (frame.lightColor.xyz * _1568), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1693 * ((_1959 * _1959) * _1956))) * (((_1160 * _1917) * _1917) * (64.0 / fma(_1842, _1176, _961 * length(float3(_1154 * float2(dot(_1133, _1758), dot(_1146, _1758)), 128.0 * _1842)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1767 * _1767) / fast::max(_1753, 9.9999997473787516355514526367188e-05)) * _1786) * _1786)) * _1842), float3(65504.0));
    float3 _2024 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2027 = dot(_2024, _2024);
    float3 _2032 = _2024 * rsqrt(fast::max(_2027, 9.9999999392252902907785028219223e-09));
    float _2036 = _2027 * float(frame.punctualLights[1].positionFalloff.w);
    float _2041 = fast::clamp(fma(-_2036, _2036, 1.0), 0.0, 1.0);
    float _2060 = fast::clamp(fma(dot(-_2032, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2166 = fast::normalize(_941 + _2032);
    float _2116 = fast::clamp(dot(_935, _2032), 0.0, 1.0);
    float _2120 = fast::clamp(dot(_935, _2166), 0.0, 1.0);
    float2 _2183 = float2(dot(_1133, _2166), dot(_1146, _2166)) * _1152;
    float _2191 = 1.0 / fma(_2120, _2120, dot(_2183, _2183));
    float _2230 = 1.0 - fast::clamp(dot(_2032, _2166), 0.0, 1.0);
    float _2233 = _2230 * _2230;
    out.fragColor = float4(_1989 + fast::min(((float3(params.facet_f0) + (_1693 * ((_2233 * _2233) * _2230))) * (((_1160 * _2191) * _2191) * (64.0 / fma(_2116, _1176, _961 * length(float3(_1154 * float2(dot(_1133, _2032), dot(_1146, _2032)), 128.0 * _2116)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2041 * _2041) / fast::max(_2027, 9.9999997473787516355514526367188e-05)) * _2060) * _2060)) * _2116), float3(65504.0)), 1.0);
    return out;
}

