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
    float3 _1077 = in.v_tangent.xyz - (_929 * dot(_929, in.v_tangent.xyz));
    float _1079 = _929.z;
    float3 _2179;
    if (abs(_1079) < 0.5)
    {
        _2179 = float3(-_929.y, _929.x, 0.0);
    }
    else
    {
        _2179 = float3(0.0, -_1079, _929.y);
    }
    float3 _1106 = fast::normalize(select(_2179, _1077, bool3(dot(_1077, _1077) > 0.001000000047497451305389404296875)));
    float _955 = fast::max(dot(_929, _935), 9.9999997473787516355514526367188e-05);
    float3 _1119 = cross(_929, _1106);
    float _1170 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1165 = fast::clamp(float2(1.0 + _1170, 1.0 - _1170) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1125 = float2(1.0) / _1165;
    float2 _1127 = _1165 * 128.0;
    float _1133 = 0.3183098733425140380859375 * (_1125.x * _1125.y);
    float _1149 = length(float3(_1127 * float2(dot(_1106, _935), dot(_1119, _935)), 128.0 * _955));
    float3 _2195 = select(_1119, _1106, bool3(_1170 >= 0.0));
    float _1399 = dot(_2195, _935);
    float _1406 = fast::min(abs(_1170) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1411 = fma(-_1406, 1.0 - _955, 1.0);
    float _1414 = _1406 * _1399;
    float4 _1454 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_955, params.facet_perceptualRoughness), level(0.0));
    float3 _1524 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1527 = dot(_1524, _1524);
    float3 _1532 = _1524 * rsqrt(fast::max(_1527, 9.9999999392252902907785028219223e-09));
    float _1536 = _1527 * float(frame.punctualLights[0].positionFalloff.w);
    float _1541 = fast::clamp(fma(-_1536, _1536, 1.0), 0.0, 1.0);
    float _1560 = fast::clamp(fma(dot(-_1532, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1666 = fast::normalize(_935 + _1532);
    float _1616 = fast::clamp(dot(_929, _1532), 0.0, 1.0);
    float _1620 = fast::clamp(dot(_929, _1666), 0.0, 1.0);
    float2 _1683 = float2(dot(_1106, _1666), dot(_1119, _1666)) * _1125;
    float _1691 = 1.0 / fma(_1620, _1620, dot(_1683, _1683));
    float _1730 = 1.0 - fast::clamp(dot(_1532, _1666), 0.0, 1.0);
    float _1733 = _1730 * _1730;
    float3 _1741 = float3(1.0) - float3(params.facet_f0);
    float3 _1798 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1801 = dot(_1798, _1798);
    float3 _1806 = _1798 * rsqrt(fast::max(_1801, 9.9999999392252902907785028219223e-09));
    float _1810 = _1801 * float(frame.punctualLights[1].positionFalloff.w);
    float _1815 = fast::clamp(fma(-_1810, _1810, 1.0), 0.0, 1.0);
    float _1834 = fast::clamp(fma(dot(-_1806, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1940 = fast::normalize(_935 + _1806);
    float _1890 = fast::clamp(dot(_929, _1806), 0.0, 1.0);
    float _1894 = fast::clamp(dot(_929, _1940), 0.0, 1.0);
    float2 _1957 = float2(dot(_1106, _1940), dot(_1119, _1940)) * _1125;
    float _1965 = 1.0 / fma(_1894, _1894, dot(_1957, _1957));
    float _2004 = 1.0 - fast::clamp(dot(_1806, _1940), 0.0, 1.0);
    float _2007 = _2004 * _2004;
    float3 _2037 = fma(facet_environment.sample(facet_environmentSmplr, ((((_929 * _1411) + (_2195 * _1414)) * (512.0 * fma(_1411, _955, _1414 * _1399))) - (_935 * (256.0 * fma(_1411, _1411, _1414 * _1414)))), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1454.xxx, _1454.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1454.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1741 * ((_1733 * _1733) * _1730))) * (((_1133 * _1691) * _1691) * (64.0 / fma(_1616, _1149, _955 * length(float3(_1127 * float2(dot(_1106, _1532), dot(_1119, _1532)), 128.0 * _1616)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1541 * _1541) / fast::max(_1527, 9.9999997473787516355514526367188e-05)) * _1560) * _1560)) * _1616), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1741 * ((_2007 * _2007) * _2004))) * (((_1133 * _1965) * _1965) * (64.0 / fma(_1890, _1149, _955 * length(float3(_1127 * float2(dot(_1106, _1806), dot(_1119, _1806)), 128.0 * _1890)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1815 * _1815) / fast::max(_1801, 9.9999997473787516355514526367188e-05)) * _1834) * _1834)) * _1890), float3(65504.0));
    out.fragColor = float4(_2037, 1.0);
    return out;
}

