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
    float3 _933 = fast::normalize(in.v_normal);
    float3 _939 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1081 = in.v_tangent.xyz - (_933 * dot(_933, in.v_tangent.xyz));
    float _1083 = _933.z;
    float3 _2186;
    if (abs(_1083) < 0.5)
    {
        _2186 = float3(-_933.y, _933.x, 0.0);
    }
    else
    {
        _2186 = float3(0.0, -_1083, _933.y);
    }
    float3 _1110 = fast::normalize(select(_2186, _1081, bool3(dot(_1081, _1081) > 0.001000000047497451305389404296875)));
    float _959 = fast::max(dot(_933, _939), 9.9999997473787516355514526367188e-05);
    float3 _1123 = cross(_933, _1110);
    float _1174 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1169 = fast::clamp(float2(1.0 + _1174, 1.0 - _1174) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1129 = float2(1.0) / _1169;
    float2 _1131 = _1169 * 128.0;
    float _1137 = 0.3183098733425140380859375 * (_1129.x * _1129.y);
    float _1153 = length(float3(_1131 * float2(dot(_1110, _939), dot(_1123, _939)), 128.0 * _959));
    float3 _2202 = select(_1123, _1110, bool3(_1174 >= 0.0));
    float _1403 = dot(_2202, _939);
    float _1410 = fast::min(abs(_1174) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1415 = fma(-_1410, 1.0 - _959, 1.0);
    float _1418 = _1410 * _1403;
    float4 _1458 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_959, params.facet_perceptualRoughness), level(0.0));
    float3 _1531 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1534 = dot(_1531, _1531);
    float3 _1539 = _1531 * rsqrt(fast::max(_1534, 9.9999999392252902907785028219223e-09));
    float _1543 = _1534 * float(frame.punctualLights[0].positionFalloff.w);
    float _1548 = fast::clamp(fma(-_1543, _1543, 1.0), 0.0, 1.0);
    float _1567 = fast::clamp(fma(dot(-_1539, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1673 = fast::normalize(_939 + _1539);
    float _1623 = fast::clamp(dot(_933, _1539), 0.0, 1.0);
    float _1627 = fast::clamp(dot(_933, _1673), 0.0, 1.0);
    float2 _1690 = float2(dot(_1110, _1673), dot(_1123, _1673)) * _1129;
    float _1698 = 1.0 / fma(_1627, _1627, dot(_1690, _1690));
    float _1737 = 1.0 - fast::clamp(dot(_1539, _1673), 0.0, 1.0);
    float _1740 = _1737 * _1737;
    float3 _1748 = float3(1.0) - float3(params.facet_f0);
    float3 _1805 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1808 = dot(_1805, _1805);
    float3 _1813 = _1805 * rsqrt(fast::max(_1808, 9.9999999392252902907785028219223e-09));
    float _1817 = _1808 * float(frame.punctualLights[1].positionFalloff.w);
    float _1822 = fast::clamp(fma(-_1817, _1817, 1.0), 0.0, 1.0);
    float _1841 = fast::clamp(fma(dot(-_1813, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1947 = fast::normalize(_939 + _1813);
    float _1897 = fast::clamp(dot(_933, _1813), 0.0, 1.0);
    float _1901 = fast::clamp(dot(_933, _1947), 0.0, 1.0);
    float2 _1964 = float2(dot(_1110, _1947), dot(_1123, _1947)) * _1129;
    float _1972 = 1.0 / fma(_1901, _1901, dot(_1964, _1964));
    float _2011 = 1.0 - fast::clamp(dot(_1813, _1947), 0.0, 1.0);
    float _2014 = _2011 * _2011;
    float3 _2044 = fma(facet_environment.sample(facet_environmentSmplr, ((((_933 * _1415) + (_2202 * _1418)) * (512.0 * fma(_1415, _959, _1418 * _1403))) - (_939 * (256.0 * fma(_1415, _1415, _1418 * _1418)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1458.xxx, _1458.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1458.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1748 * ((_1740 * _1740) * _1737))) * (((_1137 * _1698) * _1698) * (64.0 / fma(_1623, _1153, _959 * length(float3(_1131 * float2(dot(_1110, _1539), dot(_1123, _1539)), 128.0 * _1623)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1548 * _1548) / fast::max(_1534, 9.9999997473787516355514526367188e-05)) * _1567) * _1567)) * _1623), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1748 * ((_2014 * _2014) * _2011))) * (((_1137 * _1972) * _1972) * (64.0 / fma(_1897, _1153, _959 * length(float3(_1131 * float2(dot(_1110, _1813), dot(_1123, _1813)), 128.0 * _1897)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1822 * _1822) / fast::max(_1808, 9.9999997473787516355514526367188e-05)) * _1841) * _1841)) * _1897), float3(65504.0));
    out.fragColor = float4(_2044, 1.0);
    return out;
}

