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
    float3 _1098 = in.v_tangent.xyz - (_929 * dot(_929, in.v_tangent.xyz));
    float _1100 = _929.z;
    float3 _2398;
    if (abs(_1100) < 0.5)
    {
        _2398 = float3(-_929.y, _929.x, 0.0);
    }
    else
    {
        _2398 = float3(0.0, -_1100, _929.y);
    }
    float3 _1127 = fast::normalize(select(_2398, _1098, bool3(dot(_1098, _1098) > 0.001000000047497451305389404296875)));
    float _955 = fast::max(dot(_929, _935), 9.9999997473787516355514526367188e-05);
    float3 _1140 = cross(_929, _1127);
    float _1191 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1186 = fast::clamp(float2(1.0 + _1191, 1.0 - _1191) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1146 = float2(1.0) / _1186;
    float2 _1148 = _1186 * 128.0;
    float _1154 = 0.3183098733425140380859375 * (_1146.x * _1146.y);
    float _1170 = length(float3(_1148 * float2(dot(_1127, _935), dot(_1140, _935)), 128.0 * _955));
    float3 _2414 = select(_1140, _1127, bool3(_1191 >= 0.0));
    float _1420 = dot(_2414, _935);
    float _1427 = fast::min(abs(_1191) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1432 = fma(-_1427, 1.0 - _955, 1.0);
    float _1435 = _1427 * _1420;
    float4 _1475 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_955, params.facet_perceptualRoughness), level(0.0));
    float3 _1607 = fast::normalize(_935 + frame.lightDirection.xyz);
    float _1557 = fast::clamp(dot(_929, frame.lightDirection.xyz), 0.0, 1.0);
    float _1561 = fast::clamp(dot(_929, _1607), 0.0, 1.0);
    float2 _1624 = float2(dot(_1127, _1607), dot(_1140, _1607)) * _1146;
    float _1632 = 1.0 / fma(_1561, _1561, dot(_1624, _1624));
    float _1671 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1607), 0.0, 1.0);
    float _1674 = _1671 * _1671;
    float3 _1682 = float3(1.0) - float3(params.facet_f0);
    float3 _1739 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1742 = dot(_1739, _1739);
    float3 _1747 = _1739 * rsqrt(fast::max(_1742, 9.9999999392252902907785028219223e-09));
    float _1751 = _1742 * float(frame.punctualLights[0].positionFalloff.w);
    float _1756 = fast::clamp(fma(-_1751, _1751, 1.0), 0.0, 1.0);
    float _1775 = fast::clamp(fma(dot(-_1747, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1881 = fast::normalize(_935 + _1747);
    float _1831 = fast::clamp(dot(_929, _1747), 0.0, 1.0);
    float _1835 = fast::clamp(dot(_929, _1881), 0.0, 1.0);
    float2 _1898 = float2(dot(_1127, _1881), dot(_1140, _1881)) * _1146;
    float _1906 = 1.0 / fma(_1835, _1835, dot(_1898, _1898));
    float _1945 = 1.0 - fast::clamp(dot(_1747, _1881), 0.0, 1.0);
    float _1948 = _1945 * _1945;
    float3 _1978 = fma(facet_environment.sample(facet_environmentSmplr, ((((_929 * _1432) + (_2414 * _1435)) * (512.0 * fma(_1432, _955, _1435 * _1420))) - (_935 * (256.0 * fma(_1432, _1432, _1435 * _1435)))), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1475.xxx, _1475.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1475.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1682 * ((_1674 * _1674) * _1671))) * (((_1154 * _1632) * _1632) * (64.0 / fma(_1557, _1170, _955 * length(float3(_1148 * float2(dot(_1127, frame.lightDirection.xyz), dot(_1140, frame.lightDirection.xyz)), 128.0 * _1557)))))) * (frame.lightColor.xyz * _1557), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1682 * ((_1948 * _1948) * _1945))) * (((_1154 * _1906) * _1906) * (64.0 / fma(_1831, _1170, _955 * length(float3(_1148 * float2(dot(_1127, _1747), dot(_1140, _1747)), 128.0 * _1831)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1756 * _1756) / fast::max(_1742, 9.9999997473787516355514526367188e-05)) * _1775) * _1775)) * _1831), float3(65504.0));
    float3 _2013 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2016 = dot(_2013, _2013);
    float3 _2021 = _2013 * rsqrt(fast::max(_2016, 9.9999999392252902907785028219223e-09));
    float _2025 = _2016 * float(frame.punctualLights[1].positionFalloff.w);
    float _2030 = fast::clamp(fma(-_2025, _2025, 1.0), 0.0, 1.0);
    float _2049 = fast::clamp(fma(dot(-_2021, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2155 = fast::normalize(_935 + _2021);
    float _2105 = fast::clamp(dot(_929, _2021), 0.0, 1.0);
    float _2109 = fast::clamp(dot(_929, _2155), 0.0, 1.0);
    float2 _2172 = float2(dot(_1127, _2155), dot(_1140, _2155)) * _1146;
    float _2180 = 1.0 / fma(_2109, _2109, dot(_2172, _2172));
    float _2219 = 1.0 - fast::clamp(dot(_2021, _2155), 0.0, 1.0);
    float _2222 = _2219 * _2219;
    out.fragColor = float4(_1978 + fast::min(((float3(params.facet_f0) + (_1682 * ((_2222 * _2222) * _2219))) * (((_1154 * _2180) * _2180) * (64.0 / fma(_2105, _1170, _955 * length(float3(_1148 * float2(dot(_1127, _2021), dot(_1140, _2021)), 128.0 * _2105)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2030 * _2030) / fast::max(_2016, 9.9999997473787516355514526367188e-05)) * _2049) * _2049)) * _2105), float3(65504.0)), 1.0);
    return out;
}

