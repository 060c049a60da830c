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
    float3 _929 = fast::normalize(in.v_normal);
    float3 _935 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1078 = in.v_tangent.xyz - (_929 * dot(_929, in.v_tangent.xyz));
    float _1080 = _929.z;
    float3 _2180;
    if (abs(_1080) < 0.5)
    {
        _2180 = float3(-_929.y, _929.x, 0.0);
    }
    else
    {
        _2180 = float3(0.0, -_1080, _929.y);
    }
    float3 _1107 = fast::normalize(select(_2180, _1078, bool3(dot(_1078, _1078) > 0.001000000047497451305389404296875)));
    float _955 = fast::max(dot(_929, _935), 9.9999997473787516355514526367188e-05);
    float3 _1120 = cross(_929, _1107);
    float _1171 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1166 = fast::clamp(float2(1.0 + _1171, 1.0 - _1171) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1126 = float2(1.0) / _1166;
    float2 _1128 = _1166 * 128.0;
    float _1134 = 0.3183098733425140380859375 * (_1126.x * _1126.y);
    float _1150 = length(float3(_1128 * float2(dot(_1107, _935), dot(_1120, _935)), 128.0 * _955));
    float3 _2196 = select(_1120, _1107, bool3(_1171 >= 0.0));
    float _1400 = dot(_2196, _935);
    float _1407 = fast::min(abs(_1171) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1412 = fma(-_1407, 1.0 - _955, 1.0);
    float _1415 = _1407 * _1400;
    float4 _1455 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_955, params.facet_perceptualRoughness), level(0.0));
    float3 _1525 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1528 = dot(_1525, _1525);
    float3 _1533 = _1525 * rsqrt(fast::max(_1528, 9.9999999392252902907785028219223e-09));
    float _1537 = _1528 * float(frame.punctualLights[0].positionFalloff.w);
    float _1542 = fast::clamp(fma(-_1537, _1537, 1.0), 0.0, 1.0);
    float _1561 = fast::clamp(fma(dot(-_1533, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1667 = fast::normalize(_935 + _1533);
    float _1617 = fast::clamp(dot(_929, _1533), 0.0, 1.0);
    float _1621 = fast::clamp(dot(_929, _1667), 0.0, 1.0);
    float2 _1684 = float2(dot(_1107, _1667), dot(_1120, _1667)) * _1126;
    float _1692 = 1.0 / fma(_1621, _1621, dot(_1684, _1684));
    float _1731 = 1.0 - fast::clamp(dot(_1533, _1667), 0.0, 1.0);
    float _1734 = _1731 * _1731;
    float3 _1742 = float3(1.0) - float3(params.facet_f0);
    float3 _1799 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1802 = dot(_1799, _1799);
    float3 _1807 = _1799 * rsqrt(fast::max(_1802, 9.9999999392252902907785028219223e-09));
    float _1811 = _1802 * float(frame.punctualLights[1].positionFalloff.w);
    float _1816 = fast::clamp(fma(-_1811, _1811, 1.0), 0.0, 1.0);
    float _1835 = fast::clamp(fma(dot(-_1807, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1941 = fast::normalize(_935 + _1807);
    float _1891 = fast::clamp(dot(_929, _1807), 0.0, 1.0);
    float _1895 = fast::clamp(dot(_929, _1941), 0.0, 1.0);
    float2 _1958 = float2(dot(_1107, _1941), dot(_1120, _1941)) * _1126;
    float _1966 = 1.0 / fma(_1895, _1895, dot(_1958, _1958));
    float _2005 = 1.0 - fast::clamp(dot(_1807, _1941), 0.0, 1.0);
    float _2008 = _2005 * _2005;
    float3 _2038 = fma(facet_environment.sample(facet_environmentSmplr, ((((_929 * _1412) + (_2196 * _1415)) * (512.0 * fma(_1412, _955, _1415 * _1400))) - (_935 * (256.0 * fma(_1412, _1412, _1415 * _1415)))), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1455.xxx, _1455.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1455.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1742 * ((_1734 * _1734) * _1731))) * (((_1134 * _1692) * _1692) * (64.0 / fma(_1617, _1150, _955 * length(float3(_1128 * float2(dot(_1107, _1533), dot(_1120, _1533)), 128.0 * _1617)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1542 * _1542) / fast::max(_1528, 9.9999997473787516355514526367188e-05)) * _1561) * _1561)) * _1617), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1742 * ((_2008 * _2008) * _2005))) * (((_1134 * _1966) * _1966) * (64.0 / fma(_1891, _1150, _955 * length(float3(_1128 * float2(dot(_1107, _1807), dot(_1120, _1807)), 128.0 * _1891)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1816 * _1816) / fast::max(_1802, 9.9999997473787516355514526367188e-05)) * _1835) * _1835)) * _1891), float3(65504.0));
    out.fragColor = float4(_2038, 1.0);
    return out;
}

