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
    float3 _652 = fast::normalize(in.v_toEye);
    float2 _750 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _753 = facet_material_albedo.sample(facet_material_albedoSmplr, _750);
    float4 _763 = facet_material_relief.sample(facet_material_reliefSmplr, _750);
    float3 _767 = (_763.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _773 = fract(_750 * 4.0);
    float _775 = _773.x;
    float _782 = _773.y;
    float3 _1289;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1289 = fast::normalize(in.v_normal);
            break;
        }
        _1289 = fast::normalize(((in.v_tangent.xyz * _767.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _767.y)) + (in.v_normal * _767.z));
        break;
    } while(false);
    float3 _967 = fast::clamp(_753.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _976 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_775, 1.0 - _775), fast::min(_782, 1.0 - _782)))), 0.0, 1.0);
    float _1057 = fast::max(dot(_1289, _652), 9.9999997473787516355514526367188e-05);
    float4 _1122 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1057, params.facet_perceptualRoughness), level(0.0));
    float3 _1189 = fma(_967 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1289.y)) + (frame.sh[2].xyz * _1289.z)) + (frame.sh[3].xyz * _1289.x)) + (((((frame.sh[4].xyz * (_1289.x * _1289.y)) + (frame.sh[5].xyz * (_1289.y * _1289.z))) + (frame.sh[6].xyz * fma(3.0 * _1289.z, _1289.z, -1.0))) + (frame.sh[7].xyz * (_1289.x * _1289.z))) + (frame.sh[8].xyz * fma(_1289.x, _1289.x, -(_1289.y * _1289.y)))), float3(0.0)), fast::max(float3(_976), ((((((_967 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _976) + ((_967 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _976) + ((_967 * 2.755199909210205078125) + float3(0.69029998779296875))) * _976), (facet_environment.sample(facet_environmentSmplr, reflect(-_652, _1289), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1122.xxx, _1122.yyy, float3(0.039999999105930328369140625)) * (float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1122.y) - 1.0))))) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1057 + _976)) - 1.0) + _976, 0.0, 1.0));
    out.fragColor = float4(_1189, 1.0);
    return out;
}

