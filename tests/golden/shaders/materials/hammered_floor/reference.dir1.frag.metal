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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _789 = fast::normalize(in.v_toEye);
    float4 _903 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _907 = (_903.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1590;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1590 = fast::normalize(in.v_normal);
            break;
        }
        _1590 = fast::normalize(((in.v_tangent.xyz * _907.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _907.y)) + (in.v_normal * _907.z));
        break;
    } while(false);
    float _956 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _965 = dfdx(_1590);
    float3 _967 = dfdy(_1590);
    float _978 = _956 * _956;
    float _1178 = fast::clamp(sqrt(sqrt(fast::min(fma(_978, _978, fast::min((dot(_965, _965) + dot(_967, _967)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float _1145 = fast::max(dot(_1590, _789), 9.9999997473787516355514526367188e-05);
    float4 _1185 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1145, _1178), level(0.0));
    float3 _1204 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1185.y) - 1.0));
    float _1329 = _1178 * _1178;
    float _1271 = fast::clamp(dot(_1590, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1340 = fast::normalize(_789 + frame.lightDirection.xyz);
    float4 _1402 = float4(cross(_1590, _1340), _1329 * fast::clamp(dot(_1590, _1340), 0.0, 1.0)) * 64.0;
    float _1384 = (4096.0 * _1329) / dot(_1402, _1402);
    float _1413 = _1329 * _1329;
    float _1419 = fma(-_1329, _1329, 1.0);
    float _1446 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1340), 0.0, 1.0);
    float _1449 = _1446 * _1446;
    float3 _1471 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1590.y)) + (frame.sh[2].xyz * _1590.z)) + (frame.sh[3].xyz * _1590.x)) + (((((frame.sh[4].xyz * (_1590.x * _1590.y)) + (frame.sh[5].xyz * (_1590.y * _1590.z))) + (frame.sh[6].xyz * fma(3.0 * _1590.z, _1590.z, -1.0))) + (frame.sh[7].xyz * (_1590.x * _1590.z))) + (frame.sh[8].xyz * fma(_1590.x, _1590.x, -(_1590.y * _1590.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_789, _1590), level(_1178 * (4.0 * (2.0 - _1178)))).xyz * (mix(_1185.xxx, _1185.yyy, float3(params.facet_f0)) * _1204)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1449 * _1449) * _1446))) * (((_1384 * _1384) * 0.3183098733425140380859375) * (0.5 / fma(_1271, sqrt(fma(_1145 * _1145, _1419, _1413)), _1145 * sqrt(fma(_1271 * _1271, _1419, _1413))))), _1204, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1271), float3(65504.0));
    out.fragColor = float4(_1471, 1.0);
    return out;
}

