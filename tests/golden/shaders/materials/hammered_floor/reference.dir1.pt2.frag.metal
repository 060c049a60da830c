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
    float3 _866 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1017 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _1021 = (_1017.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2377;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2377 = fast::normalize(in.v_normal);
            break;
        }
        _2377 = fast::normalize(((in.v_tangent.xyz * _1021.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1021.y)) + (in.v_normal * _1021.z));
        break;
    } while(false);
    float _1070 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _1079 = dfdx(_2377);
    float3 _1081 = dfdy(_2377);
    float _1092 = _1070 * _1070;
    float _1292 = fast::clamp(sqrt(sqrt(fast::min(fma(_1092, _1092, fast::min((dot(_1079, _1079) + dot(_1081, _1081)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float _1259 = fast::max(dot(_2377, _866), 9.9999997473787516355514526367188e-05);
    float4 _1299 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1259, _1292), level(0.0));
    float3 _1318 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1299.y) - 1.0));
    float _1440 = _1292 * _1292;
    float3 _1451 = fast::normalize(_866 + frame.lightDirection.xyz);
    float _1385 = fast::clamp(dot(_2377, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1489 = cross(_2377, _1451);
    float _1492 = fast::clamp(dot(_2377, _1451), 0.0, 1.0) * _1440;
    float _1501 = _1440 / fma(_1492, _1492, dot(_1489, _1489));
    float _1514 = _1440 * _1440;
    float _1520 = fma(-_1440, _1440, 1.0);
    float _1524 = sqrt(fma(_1259 * _1259, _1520, _1514));
    float _1547 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1451), 0.0, 1.0);
    float _1550 = _1547 * _1547;
    float3 _1558 = float3(1.0) - float3(params.facet_f0);
    float3 _1416 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1572 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2377.y)) + (frame.sh[2].xyz * _2377.z)) + (frame.sh[3].xyz * _2377.x)) + (((((frame.sh[4].xyz * (_2377.x * _2377.y)) + (frame.sh[5].xyz * (_2377.y * _2377.z))) + (frame.sh[6].xyz * fma(3.0 * _2377.z, _2377.z, -1.0))) + (frame.sh[7].xyz * (_2377.x * _2377.z))) + (frame.sh[8].xyz * fma(_2377.x, _2377.x, -(_2377.y * _2377.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_866, _2377), level(_1292 * 4.0)).xyz * (mix(_1299.xxx, _1299.yyy, float3(params.facet_f0)) * _1318)) + fast::min(fma((float3(params.facet_f0) + (_1558 * ((_1550 * _1550) * _1547))) * (((_1501 * _1501) * 0.3183098733425140380859375) * (0.5 / fma(_1385, _1524, _1259 * sqrt(fma(_1385 * _1385, _1520, _1514))))), _1318, _1416) * (frame.lightColor.xyz * _1385), float3(65504.0));
    float3 _1607 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1610 = dot(_1607, _1607);
    float3 _1615 = _1607 * rsqrt(fast::max(_1610, 9.9999999392252902907785028219223e-09));
    float _1619 = _1610 * float(frame.punctualLights[0].positionFalloff.w);
    float _1624 = fast::clamp(fma(-_1619, _1619, 1.0), 0.0, 1.0);
    float _1643 = fast::clamp(fma(dot(-_1615, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1769 = fast::normalize(_866 + _1615);
    float _1703 = fast::clamp(dot(_2377, _1615), 0.0, 1.0);
    float3 _1807 = cross(_2377, _1769);
    float _1810 = fast::clamp(dot(_2377, _1769), 0.0, 1.0) * _1440;
    float _1819 = _1440 / fma(_1810, _1810, dot(_1807, _1807));
    float _1865 = 1.0 - fast::clamp(dot(_1615, _1769), 0.0, 1.0);
    float _1868 = _1865 * _1865;
    float3 _1925 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1928 = dot(_1925, _1925);
    float3 _1933 = _1925 * rsqrt(fast::max(_1928, 9.9999999392252902907785028219223e-09));
    float _1937 = _1928 * float(frame.punctualLights[1].positionFalloff.w);
    float _1942 = fast::clamp(fma(-_1937, _1937, 1.0), 0.0, 1.0);
    float _1961 = fast::clamp(fma(dot(-_1933, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2087 = fast::normalize(_866 + _1933);
    float _2021 = fast::clamp(dot(_2377, _1933), 0.0, 1.0);
    float3 _2125 = cross(_2377, _2087);
    float _2128 = fast::clamp(dot(_2377, _2087), 0.0, 1.0) * _1440;
    float _2137 = _1440 / fma(_2128, _2128, dot(_2125, _2125));
    float _2183 = 1.0 - fast::clamp(dot(_1933, _2087), 0.0, 1.0);
    float _2186 = _2183 * _2183;
    float3 _2208 = (_1572 + fast::min(fma((float3(params.facet_f0) + (_1558 * ((_1868 * _1868) * _1865))) * (((_1819 * _1819) * 0.3183098733425140380859375) * (0.5 / fma(_1703, _1524, _1259 * sqrt(fma(_1703 * _1703, _1520, _1514))))), _1318, _1416) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1624 * _1624) / fast::max(_1610, 9.9999997473787516355514526367188e-05)) * _1643) * _1643)) * _1703), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1558 * ((_2186 * _2186) * _2183))) * (((_2137 * _2137) * 0.3183098733425140380859375) * (0.5 / fma(_2021, _1524, _1259 * sqrt(fma(_2021 * _2021, _1520, _1514))))), _1318, _1416) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1942 * _1942) / fast::max(_1928, 9.9999997473787516355514526367188e-05)) * _1961) * _1961)) * _2021), float3(65504.0));
    out.fragColor = float4(_2208, 1.0);
    return out;
}

