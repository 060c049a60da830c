#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float tiling;
    float roughness;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _887 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1038 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _1042 = (_1038.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2431;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2431 = fast::normalize(in.v_normal);
            break;
        }
        _2431 = fast::normalize(((in.v_tangent.xyz * _1042.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1042.y)) + (in.v_normal * _1042.z));
        break;
    } while(false);
    float _1091 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _1100 = dfdx(_2431);
    float3 _1102 = dfdy(_2431);
    float _1113 = _1091 * _1091;
    float _1313 = fast::clamp(sqrt(sqrt(fast::min(fma(_1113, _1113, fast::min((dot(_1100, _1100) + dot(_1102, _1102)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float _1280 = fast::max(dot(_2431, _887), 9.9999997473787516355514526367188e-05);
    float4 _1320 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1280, _1313), level(0.0));
    float3 _1339 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1320.y) - 1.0));
    float _1464 = _1313 * _1313;
    float _1406 = fast::clamp(dot(_2431, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1475 = fast::normalize(_887 + frame.lightDirection.xyz);
    float _1513 = 4096.0 * _1464;
    float4 _1537 = float4(cross(_2431, _1475), _1464 * fast::clamp(dot(_2431, _1475), 0.0, 1.0)) * 64.0;
    float _1519 = _1513 / dot(_1537, _1537);
    float _1548 = _1464 * _1464;
    float _1554 = fma(-_1464, _1464, 1.0);
    float _1558 = sqrt(fma(_1280 * _1280, _1554, _1548));
    float _1581 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1475), 0.0, 1.0);
    float _1584 = _1581 * _1581;
    float3 _1592 = float3(1.0) - float3(params.facet_f0);
    float3 _1440 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1606 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2431.y)) + (frame.sh[2].xyz * _2431.z)) + (frame.sh[3].xyz * _2431.x)) + (((((frame.sh[4].xyz * (_2431.x * _2431.y)) + (frame.sh[5].xyz * (_2431.y * _2431.z))) + (frame.sh[6].xyz * fma(3.0 * _2431.z, _2431.z, -1.0))) + (frame.sh[7].xyz * (_2431.x * _2431.z))) + (frame.sh[8].xyz * fma(_2431.x, _2431.x, -(_2431.y * _2431.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_887, _2431), level(_1313 * (4.0 * (2.0 - _1313)))).xyz * (mix(_1320.xxx, _1320.yyy, float3(params.facet_f0)) * _1339)) + fast::min(fma((float3(params.facet_f0) + (_1592 * ((_1584 * _1584) * _1581))) * (((_1519 * _1519) * 0.3183098733425140380859375) * (0.5 / fma(_1406, _1558, _1280 * sqrt(fma(_1406 * _1406, _1554, _1548))))), _1339, _1440) * (frame.lightColor.xyz * _1406), float3(65504.0));
    float3 _1641 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1644 = dot(_1641, _1641);
    float3 _1649 = _1641 * rsqrt(fast::max(_1644, 9.9999999392252902907785028219223e-09));
    float _1653 = _1644 * float(frame.punctualLights[0].positionFalloff.w);
    float _1658 = fast::clamp(fma(-_1653, _1653, 1.0), 0.0, 1.0);
    float _1677 = fast::clamp(fma(dot(-_1649, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1734 = fast::clamp(dot(_2431, _1649), 0.0, 1.0);
    float3 _1803 = fast::normalize(_887 + _1649);
    float4 _1865 = float4(cross(_2431, _1803), _1464 * fast::clamp(dot(_2431, _1803), 0.0, 1.0)) * 64.0;
    float _1847 = _1513 / dot(_1865, _1865);
    float _1909 = 1.0 - fast::clamp(dot(_1649, _1803), 0.0, 1.0);
    float _1912 = _1909 * _1909;
    float3 _1969 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1972 = dot(_1969, _1969);
    float3 _1977 = _1969 * rsqrt(fast::max(_1972, 9.9999999392252902907785028219223e-09));
    float _1981 = _1972 * float(frame.punctualLights[1].positionFalloff.w);
    float _1986 = fast::clamp(fma(-_1981, _1981, 1.0), 0.0, 1.0);
    float _2005 = fast::clamp(fma(dot(-_1977, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _2062 = fast::clamp(dot(_2431, _1977), 0.0, 1.0);
    float3 _2131 = fast::normalize(_887 + _1977);
    float4 _2193 = float4(cross(_2431, _2131), _1464 * fast::clamp(dot(_2431, _2131), 0.0, 1.0)) * 64.0;
    float _2175 = _1513 / dot(_2193, _2193);
    float _2237 = 1.0 - fast::clamp(dot(_1977, _2131), 0.0, 1.0);
    float _2240 = _2237 * _2237;
    float3 _2262 = (_1606 + fast::min(fma((float3(params.facet_f0) + (_1592 * ((_1912 * _1912) * _1909))) * (((_1847 * _1847) * 0.3183098733425140380859375) * (0.5 / fma(_1734, _1558, _1280 * sqrt(fma(_1734 * _1734, _1554, _1548))))), _1339, _1440) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1658 * _1658) / fast::max(_1644, 9.9999997473787516355514526367188e-05)) * _1677) * _1677)) * _1734), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1592 * ((_2240 * _2240) * _2237))) * (((_2175 * _2175) * 0.3183098733425140380859375) * (0.5 / fma(_2062, _1558, _1280 * sqrt(fma(_2062 * _2062, _1554, _1548))))), _1339, _1440) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1986 * _1986) / fast::max(_1972, 9.9999997473787516355514526367188e-05)) * _2005) * _2005)) * _2062), float3(65504.0));
    out.fragColor = float4(_2262, 1.0);
    return out;
}

