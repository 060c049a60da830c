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
    float3 _504 = fast::normalize(in.v_toEye);
    float4 _597 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _601 = (_597.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1035;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1035 = fast::normalize(in.v_normal);
            break;
        }
        _1035 = fast::normalize(((in.v_tangent.xyz * _601.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _601.y)) + (in.v_normal * _601.z));
        break;
    } while(false);
    float _650 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _659 = dfdx(_1035);
    float3 _661 = dfdy(_1035);
    float _672 = _650 * _650;
    float _872 = fast::clamp(sqrt(sqrt(fast::min(fma(_672, _672, fast::min((dot(_659, _659) + dot(_661, _661)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float4 _879 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_1035, _504), 9.9999997473787516355514526367188e-05), _872), level(0.0));
    float3 _917 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1035.y)) + (frame.sh[2].xyz * _1035.z)) + (frame.sh[3].xyz * _1035.x)) + (((((frame.sh[4].xyz * (_1035.x * _1035.y)) + (frame.sh[5].xyz * (_1035.y * _1035.z))) + (frame.sh[6].xyz * fma(3.0 * _1035.z, _1035.z, -1.0))) + (frame.sh[7].xyz * (_1035.x * _1035.z))) + (frame.sh[8].xyz * fma(_1035.x, _1035.x, -(_1035.y * _1035.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_504, _1035), level(_872 * (4.0 * (2.0 - _872)))).xyz * (mix(_879.xxx, _879.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _879.y) - 1.0)))));
    out.fragColor = float4(_917, 1.0);
    return out;
}

