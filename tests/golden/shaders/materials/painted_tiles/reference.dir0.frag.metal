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
    float3 _655 = fast::normalize(in.v_toEye);
    float2 _753 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _756 = facet_material_albedo.sample(facet_material_albedoSmplr, _753);
    float4 _766 = facet_material_relief.sample(facet_material_reliefSmplr, _753);
    float3 _770 = (_766.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _776 = fract(_753 * 4.0);
    float _778 = _776.x;
    float _785 = _776.y;
    float3 _1295;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1295 = fast::normalize(in.v_normal);
            break;
        }
        _1295 = fast::normalize(((in.v_tangent.xyz * _770.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _770.y)) + (in.v_normal * _770.z));
        break;
    } while(false);
    float3 _970 = fast::clamp(_756.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _979 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_778, 1.0 - _778), fast::min(_785, 1.0 - _785)))), 0.0, 1.0);
    float _1060 = fast::max(dot(_1295, _655), 9.9999997473787516355514526367188e-05);
    float4 _1125 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1060, params.facet_perceptualRoughness), level(0.0));
    float3 _1195 = fma(_970 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1295.y)) + (frame.sh[2].xyz * _1295.z)) + (frame.sh[3].xyz * _1295.x)) + (((((frame.sh[4].xyz * (_1295.x * _1295.y)) + (frame.sh[5].xyz * (_1295.y * _1295.z))) + (frame.sh[6].xyz * fma(3.0 * _1295.z, _1295.z, -1.0))) + (frame.sh[7].xyz * (_1295.x * _1295.z))) + (frame.sh[8].xyz * fma(_1295.x, _1295.x, -(_1295.y * _1295.y)))), float3(0.0)), fast::max(float3(_979), ((((((_970 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _979) + ((_970 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _979) + ((_970 * 2.755199909210205078125) + float3(0.69029998779296875))) * _979), (facet_environment.sample(facet_environmentSmplr, reflect(-_655, _1295), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1125.xxx, _1125.yyy, float3(0.039999999105930328369140625)) * (float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1125.y) - 1.0))))) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1060 + _979)) - 1.0) + _979, 0.0, 1.0));
    out.fragColor = float4(_1195, 1.0);
    return out;
}

