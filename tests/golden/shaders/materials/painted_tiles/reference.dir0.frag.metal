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
    float3 _507 = fast::normalize(in.v_toEye);
    float2 _594 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _597 = facet_material_albedo.sample(facet_material_albedoSmplr, _594);
    float4 _607 = facet_material_relief.sample(facet_material_reliefSmplr, _594);
    float3 _611 = (_607.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1004;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1004 = fast::normalize(in.v_normal);
            break;
        }
        _1004 = fast::normalize(((in.v_tangent.xyz * _611.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _611.y)) + (in.v_normal * _611.z));
        break;
    } while(false);
    float4 _882 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_1004, _507), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float3 _917 = fma(fast::clamp(_597.xyz, float3(0.0), float3(1.0)) * 1.0, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1004.y)) + (frame.sh[2].xyz * _1004.z)) + (frame.sh[3].xyz * _1004.x)) + (((((frame.sh[4].xyz * (_1004.x * _1004.y)) + (frame.sh[5].xyz * (_1004.y * _1004.z))) + (frame.sh[6].xyz * fma(3.0 * _1004.z, _1004.z, -1.0))) + (frame.sh[7].xyz * (_1004.x * _1004.z))) + (frame.sh[8].xyz * fma(_1004.x, _1004.x, -(_1004.y * _1004.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_507, _1004), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_882.xxx, _882.yyy, float3(0.039999999105930328369140625)) * (float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _882.y) - 1.0)))));
    out.fragColor = float4(_917, 1.0);
    return out;
}

