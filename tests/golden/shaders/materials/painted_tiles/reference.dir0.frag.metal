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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _640 = fast::normalize(in.v_toEye);
    float2 _738 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _741 = facet_material_albedo.sample(facet_material_albedoSmplr, _738);
    float4 _751 = facet_material_relief.sample(facet_material_reliefSmplr, _738);
    float3 _755 = (_751.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _761 = fract(_738 * 4.0);
    float _763 = _761.x;
    float _770 = _761.y;
    float3 _1270;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1270 = fast::normalize(in.v_normal);
            break;
        }
        _1270 = fast::normalize(((in.v_tangent.xyz * _755.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _755.y)) + (in.v_normal * _755.z));
        break;
    } while(false);
    float3 _955 = fast::clamp(_741.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _964 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_763, 1.0 - _763), fast::min(_770, 1.0 - _770)))), 0.0, 1.0);
    float _1043 = fast::max(dot(_1270, _640), 9.9999997473787516355514526367188e-05);
    float4 _1111 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1043, params.facet_perceptualRoughness), level(0.0));
    float3 _1170 = fma(_955 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1270.y)) + (frame.sh[2].xyz * _1270.z)) + (frame.sh[3].xyz * _1270.x)) + (((((frame.sh[4].xyz * (_1270.x * _1270.y)) + (frame.sh[5].xyz * (_1270.y * _1270.z))) + (frame.sh[6].xyz * fma(3.0 * _1270.z, _1270.z, -1.0))) + (frame.sh[7].xyz * (_1270.x * _1270.z))) + (frame.sh[8].xyz * fma(_1270.x, _1270.x, -(_1270.y * _1270.y)))), float3(0.0)), fast::max(float3(_964), ((((((_955 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _964) + ((_955 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _964) + ((_955 * 2.755199909210205078125) + float3(0.69029998779296875))) * _964), (facet_environment.sample(facet_environmentSmplr, reflect(-_640, _1270), level(params.facet_environmentLod)).xyz * (mix(_1111.xxx, _1111.yyy, float3(0.039999999105930328369140625)) * (float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1111.y) - 1.0))))) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1043 + _964)) - 1.0) + _964, 0.0, 1.0));
    out.fragColor = float4(_1170, 1.0);
    return out;
}

