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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _501 = fast::normalize(in.v_toEye);
    float4 _594 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _598 = (_594.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1029;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1029 = fast::normalize(in.v_normal);
            break;
        }
        _1029 = fast::normalize(((in.v_tangent.xyz * _598.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _598.y)) + (in.v_normal * _598.z));
        break;
    } while(false);
    float _647 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _656 = dfdx(_1029);
    float3 _658 = dfdy(_1029);
    float _669 = _647 * _647;
    float _869 = fast::clamp(sqrt(sqrt(fast::min(fma(_669, _669, fast::min((dot(_656, _656) + dot(_658, _658)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float4 _876 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_1029, _501), 9.9999997473787516355514526367188e-05), _869), level(0.0));
    float3 _911 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1029.y)) + (frame.sh[2].xyz * _1029.z)) + (frame.sh[3].xyz * _1029.x)) + (((((frame.sh[4].xyz * (_1029.x * _1029.y)) + (frame.sh[5].xyz * (_1029.y * _1029.z))) + (frame.sh[6].xyz * fma(3.0 * _1029.z, _1029.z, -1.0))) + (frame.sh[7].xyz * (_1029.x * _1029.z))) + (frame.sh[8].xyz * fma(_1029.x, _1029.x, -(_1029.y * _1029.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_501, _1029), level(_869 * 4.0)).xyz * (mix(_876.xxx, _876.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _876.y) - 1.0)))));
    out.fragColor = float4(_911, 1.0);
    return out;
}

