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
    float3 _933 = fast::normalize(in.v_toEye);
    float2 _1052 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1055 = facet_material_albedo.sample(facet_material_albedoSmplr, _1052);
    float4 _1065 = facet_material_relief.sample(facet_material_reliefSmplr, _1052);
    float3 _1069 = (_1065.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1075 = fract(_1052 * 4.0);
    float _1077 = _1075.x;
    float _1084 = _1075.y;
    float3 _1873;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1873 = fast::normalize(in.v_normal);
            break;
        }
        _1873 = fast::normalize(((in.v_tangent.xyz * _1069.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1069.y)) + (in.v_normal * _1069.z));
        break;
    } while(false);
    float3 _1269 = fast::clamp(_1055.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1278 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1077, 1.0 - _1077), fast::min(_1084, 1.0 - _1084)))), 0.0, 1.0);
    float _1359 = fast::max(dot(_1873, _933), 9.9999997473787516355514526367188e-05);
    float4 _1424 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1359, params.facet_perceptualRoughness), level(0.0));
    float3 _1443 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1424.y) - 1.0));
    float3 _1624 = fast::normalize(_933 + frame.lightDirection.xyz);
    float _1545 = fast::clamp(dot(_1873, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1686 = float4(cross(_1873, _1624), params.facet_alpha * fast::clamp(dot(_1873, _1624), 0.0, 1.0)) * 64.0;
    float _1668 = (4096.0 * params.facet_alpha) / dot(_1686, _1686);
    float _1697 = params.facet_alpha * params.facet_alpha;
    float _1703 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1730 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1624), 0.0, 1.0);
    float _1733 = _1730 * _1730;
    float3 _1763 = fma(_1269 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1873.y)) + (frame.sh[2].xyz * _1873.z)) + (frame.sh[3].xyz * _1873.x)) + (((((frame.sh[4].xyz * (_1873.x * _1873.y)) + (frame.sh[5].xyz * (_1873.y * _1873.z))) + (frame.sh[6].xyz * fma(3.0 * _1873.z, _1873.z, -1.0))) + (frame.sh[7].xyz * (_1873.x * _1873.z))) + (frame.sh[8].xyz * fma(_1873.x, _1873.x, -(_1873.y * _1873.y)))), float3(0.0)), fast::max(float3(_1278), ((((((_1269 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1278) + ((_1269 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1278) + ((_1269 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1278), (facet_environment.sample(facet_environmentSmplr, reflect(-_933, _1873), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1424.xxx, _1424.yyy, float3(0.039999999105930328369140625)) * _1443)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1359 + _1278)) - 1.0) + _1278, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1733 * _1733) * _1730))) * (((_1668 * _1668) * 0.3183098733425140380859375) * (0.5 / fma(_1545, sqrt(fma(_1359 * _1359, _1703, _1697)), _1359 * sqrt(fma(_1545 * _1545, _1703, _1697))))), _1443, _1269 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1545), float3(65504.0));
    out.fragColor = float4(_1763, 1.0);
    return out;
}

