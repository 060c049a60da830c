#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float tiling;
    float roughness;
    float facet_pad8;
    float facet_pad12;
    float facet_perceptualRoughness;
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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _768 = fast::normalize(in.v_toEye);
    float2 _876 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _879 = facet_material_albedo.sample(facet_material_albedoSmplr, _876);
    float4 _889 = facet_material_relief.sample(facet_material_reliefSmplr, _876);
    float3 _893 = (_889.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1555;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1555 = fast::normalize(in.v_normal);
            break;
        }
        _1555 = fast::normalize(((in.v_tangent.xyz * _893.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _893.y)) + (in.v_normal * _893.z));
        break;
    } while(false);
    float3 _1066 = fast::clamp(_879.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1101 = fast::max(dot(_1555, _768), 9.9999997473787516355514526367188e-05);
    float4 _1164 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1101, params.facet_perceptualRoughness), level(0.0));
    float3 _1183 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1164.y) - 1.0));
    float3 _1329 = fast::normalize(_768 + frame.lightDirection.xyz);
    float _1250 = fast::clamp(dot(_1555, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1367 = cross(_1555, _1329);
    float _1370 = fast::clamp(dot(_1555, _1329), 0.0, 1.0) * params.facet_alpha;
    float _1379 = params.facet_alpha / fma(_1370, _1370, dot(_1367, _1367));
    float _1392 = params.facet_alpha * params.facet_alpha;
    float _1398 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1425 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1329), 0.0, 1.0);
    float _1428 = _1425 * _1425;
    float3 _1458 = fma(_1066, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1555.y)) + (frame.sh[2].xyz * _1555.z)) + (frame.sh[3].xyz * _1555.x)) + (((((frame.sh[4].xyz * (_1555.x * _1555.y)) + (frame.sh[5].xyz * (_1555.y * _1555.z))) + (frame.sh[6].xyz * fma(3.0 * _1555.z, _1555.z, -1.0))) + (frame.sh[7].xyz * (_1555.x * _1555.z))) + (frame.sh[8].xyz * fma(_1555.x, _1555.x, -(_1555.y * _1555.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_768, _1555), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1164.xxx, _1164.yyy, float3(0.039999999105930328369140625)) * _1183)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1428 * _1428) * _1425))) * (((_1379 * _1379) * 0.3183098733425140380859375) * (0.5 / fma(_1250, sqrt(fma(_1101 * _1101, _1398, _1392)), _1101 * sqrt(fma(_1250 * _1250, _1398, _1392))))), _1183, _1066 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1250), float3(65504.0));
    out.fragColor = float4(_1458, 1.0);
    return out;
}

