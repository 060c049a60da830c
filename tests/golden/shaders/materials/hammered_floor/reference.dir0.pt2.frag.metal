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
    float4 _996 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _1000 = (_996.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2116;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2116 = fast::normalize(in.v_normal);
            break;
        }
        _2116 = fast::normalize(((in.v_tangent.xyz * _1000.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1000.y)) + (in.v_normal * _1000.z));
        break;
    } while(false);
    float _1049 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _1058 = dfdx(_2116);
    float3 _1060 = dfdy(_2116);
    float _1071 = _1049 * _1049;
    float _1271 = fast::clamp(sqrt(sqrt(fast::min(fma(_1071, _1071, fast::min((dot(_1058, _1058) + dot(_1060, _1060)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float _1238 = fast::max(dot(_2116, _866), 9.9999997473787516355514526367188e-05);
    float4 _1278 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1238, _1271), level(0.0));
    float3 _1297 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1278.y) - 1.0));
    float3 _1348 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1351 = dot(_1348, _1348);
    float3 _1356 = _1348 * rsqrt(fast::max(_1351, 9.9999999392252902907785028219223e-09));
    float _1360 = _1351 * float(frame.punctualLights[0].positionFalloff.w);
    float _1365 = fast::clamp(fma(-_1360, _1360, 1.0), 0.0, 1.0);
    float _1384 = fast::clamp(fma(dot(-_1356, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1499 = _1271 * _1271;
    float3 _1510 = fast::normalize(_866 + _1356);
    float _1444 = fast::clamp(dot(_2116, _1356), 0.0, 1.0);
    float3 _1548 = cross(_2116, _1510);
    float _1551 = fast::clamp(dot(_2116, _1510), 0.0, 1.0) * _1499;
    float _1560 = _1499 / fma(_1551, _1551, dot(_1548, _1548));
    float _1573 = _1499 * _1499;
    float _1579 = fma(-_1499, _1499, 1.0);
    float _1583 = sqrt(fma(_1238 * _1238, _1579, _1573));
    float _1606 = 1.0 - fast::clamp(dot(_1356, _1510), 0.0, 1.0);
    float _1609 = _1606 * _1606;
    float3 _1617 = float3(1.0) - float3(params.facet_f0);
    float3 _1475 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1631 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2116.y)) + (frame.sh[2].xyz * _2116.z)) + (frame.sh[3].xyz * _2116.x)) + (((((frame.sh[4].xyz * (_2116.x * _2116.y)) + (frame.sh[5].xyz * (_2116.y * _2116.z))) + (frame.sh[6].xyz * fma(3.0 * _2116.z, _2116.z, -1.0))) + (frame.sh[7].xyz * (_2116.x * _2116.z))) + (frame.sh[8].xyz * fma(_2116.x, _2116.x, -(_2116.y * _2116.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_866, _2116), level(_1271 * 4.0)).xyz * (mix(_1278.xxx, _1278.yyy, float3(params.facet_f0)) * _1297)) + fast::min(fma((float3(params.facet_f0) + (_1617 * ((_1609 * _1609) * _1606))) * (((_1560 * _1560) * 0.3183098733425140380859375) * (0.5 / fma(_1444, _1583, _1238 * sqrt(fma(_1444 * _1444, _1579, _1573))))), _1297, _1475) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1365 * _1365) / fast::max(_1351, 9.9999997473787516355514526367188e-05)) * _1384) * _1384)) * _1444), float3(65504.0));
    float3 _1666 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1669 = dot(_1666, _1666);
    float3 _1674 = _1666 * rsqrt(fast::max(_1669, 9.9999999392252902907785028219223e-09));
    float _1678 = _1669 * float(frame.punctualLights[1].positionFalloff.w);
    float _1683 = fast::clamp(fma(-_1678, _1678, 1.0), 0.0, 1.0);
    float _1702 = fast::clamp(fma(dot(-_1674, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1828 = fast::normalize(_866 + _1674);
    float _1762 = fast::clamp(dot(_2116, _1674), 0.0, 1.0);
    float3 _1866 = cross(_2116, _1828);
    float _1869 = fast::clamp(dot(_2116, _1828), 0.0, 1.0) * _1499;
    float _1878 = _1499 / fma(_1869, _1869, dot(_1866, _1866));
    float _1924 = 1.0 - fast::clamp(dot(_1674, _1828), 0.0, 1.0);
    float _1927 = _1924 * _1924;
    out.fragColor = float4(_1631 + fast::min(fma((float3(params.facet_f0) + (_1617 * ((_1927 * _1927) * _1924))) * (((_1878 * _1878) * 0.3183098733425140380859375) * (0.5 / fma(_1762, _1583, _1238 * sqrt(fma(_1762 * _1762, _1579, _1573))))), _1297, _1475) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1683 * _1683) / fast::max(_1669, 9.9999997473787516355514526367188e-05)) * _1702) * _1702)) * _1762), float3(65504.0)), 1.0);
    return out;
}

