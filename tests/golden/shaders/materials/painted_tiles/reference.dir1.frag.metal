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
    float2 _879 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _882 = facet_material_albedo.sample(facet_material_albedoSmplr, _879);
    float4 _892 = facet_material_relief.sample(facet_material_reliefSmplr, _879);
    float3 _896 = (_892.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1558;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1558 = fast::normalize(in.v_normal);
            break;
        }
        _1558 = fast::normalize(((in.v_tangent.xyz * _896.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _896.y)) + (in.v_normal * _896.z));
        break;
    } while(false);
    float3 _1069 = fast::clamp(_882.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1104 = fast::max(dot(_1558, _768), 9.9999997473787516355514526367188e-05);
    float4 _1167 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1104, params.facet_perceptualRoughness), level(0.0));
    float3 _1186 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1167.y) - 1.0));
    float3 _1332 = fast::normalize(_768 + frame.lightDirection.xyz);
    float _1253 = fast::clamp(dot(_1558, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1370 = cross(_1558, _1332);
    float _1373 = fast::clamp(dot(_1558, _1332), 0.0, 1.0) * params.facet_alpha;
    float _1382 = params.facet_alpha / fma(_1373, _1373, dot(_1370, _1370));
    float _1395 = params.facet_alpha * params.facet_alpha;
    float _1401 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1428 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1332), 0.0, 1.0);
    float _1431 = _1428 * _1428;
    float3 _1461 = fma(_1069, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1558.y)) + (frame.sh[2].xyz * _1558.z)) + (frame.sh[3].xyz * _1558.x)) + (((((frame.sh[4].xyz * (_1558.x * _1558.y)) + (frame.sh[5].xyz * (_1558.y * _1558.z))) + (frame.sh[6].xyz * fma(3.0 * _1558.z, _1558.z, -1.0))) + (frame.sh[7].xyz * (_1558.x * _1558.z))) + (frame.sh[8].xyz * fma(_1558.x, _1558.x, -(_1558.y * _1558.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_768, _1558), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1167.xxx, _1167.yyy, float3(0.039999999105930328369140625)) * _1186)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1431 * _1431) * _1428))) * (((_1382 * _1382) * 0.3183098733425140380859375) * (0.5 / fma(_1253, sqrt(fma(_1104 * _1104, _1401, _1395)), _1104 * sqrt(fma(_1253 * _1253, _1401, _1395))))), _1186, _1069 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1253), float3(65504.0));
    out.fragColor = float4(_1461, 1.0);
    return out;
}

