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
    float4 _1017 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _1021 = (_1017.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2160;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2160 = fast::normalize(in.v_normal);
            break;
        }
        _2160 = fast::normalize(((in.v_tangent.xyz * _1021.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1021.y)) + (in.v_normal * _1021.z));
        break;
    } while(false);
    float _1070 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _1079 = dfdx(_2160);
    float3 _1081 = dfdy(_2160);
    float _1092 = _1070 * _1070;
    float _1292 = fast::clamp(sqrt(sqrt(fast::min(fma(_1092, _1092, fast::min((dot(_1079, _1079) + dot(_1081, _1081)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float _1259 = fast::max(dot(_2160, _887), 9.9999997473787516355514526367188e-05);
    float4 _1299 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1259, _1292), level(0.0));
    float3 _1318 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1299.y) - 1.0));
    float3 _1372 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1375 = dot(_1372, _1372);
    float3 _1380 = _1372 * rsqrt(fast::max(_1375, 9.9999999392252902907785028219223e-09));
    float _1384 = _1375 * float(frame.punctualLights[0].positionFalloff.w);
    float _1389 = fast::clamp(fma(-_1384, _1384, 1.0), 0.0, 1.0);
    float _1408 = fast::clamp(fma(dot(-_1380, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1523 = _1292 * _1292;
    float _1465 = fast::clamp(dot(_2160, _1380), 0.0, 1.0);
    float3 _1534 = fast::normalize(_887 + _1380);
    float _1572 = 4096.0 * _1523;
    float4 _1596 = float4(cross(_2160, _1534), _1523 * fast::clamp(dot(_2160, _1534), 0.0, 1.0)) * 64.0;
    float _1578 = _1572 / dot(_1596, _1596);
    float _1607 = _1523 * _1523;
    float _1613 = fma(-_1523, _1523, 1.0);
    float _1617 = sqrt(fma(_1259 * _1259, _1613, _1607));
    float _1640 = 1.0 - fast::clamp(dot(_1380, _1534), 0.0, 1.0);
    float _1643 = _1640 * _1640;
    float3 _1651 = float3(1.0) - float3(params.facet_f0);
    float3 _1499 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1665 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2160.y)) + (frame.sh[2].xyz * _2160.z)) + (frame.sh[3].xyz * _2160.x)) + (((((frame.sh[4].xyz * (_2160.x * _2160.y)) + (frame.sh[5].xyz * (_2160.y * _2160.z))) + (frame.sh[6].xyz * fma(3.0 * _2160.z, _2160.z, -1.0))) + (frame.sh[7].xyz * (_2160.x * _2160.z))) + (frame.sh[8].xyz * fma(_2160.x, _2160.x, -(_2160.y * _2160.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_887, _2160), level(_1292 * (4.0 * (2.0 - _1292)))).xyz * (mix(_1299.xxx, _1299.yyy, float3(params.facet_f0)) * _1318)) + fast::min(fma((float3(params.facet_f0) + (_1651 * ((_1643 * _1643) * _1640))) * (((_1578 * _1578) * 0.3183098733425140380859375) * (0.5 / fma(_1465, _1617, _1259 * sqrt(fma(_1465 * _1465, _1613, _1607))))), _1318, _1499) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1389 * _1389) / fast::max(_1375, 9.9999997473787516355514526367188e-05)) * _1408) * _1408)) * _1465), float3(65504.0));
    float3 _1700 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1703 = dot(_1700, _1700);
    float3 _1708 = _1700 * rsqrt(fast::max(_1703, 9.9999999392252902907785028219223e-09));
    float _1712 = _1703 * float(frame.punctualLights[1].positionFalloff.w);
    float _1717 = fast::clamp(fma(-_1712, _1712, 1.0), 0.0, 1.0);
    float _1736 = fast::clamp(fma(dot(-_1708, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1793 = fast::clamp(dot(_2160, _1708), 0.0, 1.0);
    float3 _1862 = fast::normalize(_887 + _1708);
    float4 _1924 = float4(cross(_2160, _1862), _1523 * fast::clamp(dot(_2160, _1862), 0.0, 1.0)) * 64.0;
    float _1906 = _1572 / dot(_1924, _1924);
    float _1968 = 1.0 - fast::clamp(dot(_1708, _1862), 0.0, 1.0);
    float _1971 = _1968 * _1968;
    out.fragColor = float4(_1665 + fast::min(fma((float3(params.facet_f0) + (_1651 * ((_1971 * _1971) * _1968))) * (((_1906 * _1906) * 0.3183098733425140380859375) * (0.5 / fma(_1793, _1617, _1259 * sqrt(fma(_1793 * _1793, _1613, _1607))))), _1318, _1499) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1717 * _1717) / fast::max(_1703, 9.9999997473787516355514526367188e-05)) * _1736) * _1736)) * _1793), float3(65504.0)), 1.0);
    return out;
}

