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
    float3 _934 = fast::normalize(in.v_toEye);
    float2 _1053 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1056 = facet_material_albedo.sample(facet_material_albedoSmplr, _1053);
    float4 _1066 = facet_material_relief.sample(facet_material_reliefSmplr, _1053);
    float3 _1070 = (_1066.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1076 = fract(_1053 * 4.0);
    float _1078 = _1076.x;
    float _1085 = _1076.y;
    float3 _1875;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1875 = fast::normalize(in.v_normal);
            break;
        }
        _1875 = fast::normalize(((in.v_tangent.xyz * _1070.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1070.y)) + (in.v_normal * _1070.z));
        break;
    } while(false);
    float3 _1270 = fast::clamp(_1056.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1279 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1078, 1.0 - _1078), fast::min(_1085, 1.0 - _1085)))), 0.0, 1.0);
    float _1360 = fast::max(dot(_1875, _934), 9.9999997473787516355514526367188e-05);
    float4 _1425 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1360, params.facet_perceptualRoughness), level(0.0));
    float3 _1444 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1425.y) - 1.0));
    float3 _1622 = fast::normalize(_934 + frame.lightDirection.xyz);
    float _1543 = fast::clamp(dot(_1875, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1680 = cross(_1875, _1622) * 64.0;
    float _1684 = fast::clamp(dot(_1875, _1622), 0.0, 1.0) * (64.0 * params.facet_alpha);
    float _1667 = (4096.0 * params.facet_alpha) / fma(_1684, _1684, dot(_1680, _1680));
    float _1699 = params.facet_alpha * params.facet_alpha;
    float _1705 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1732 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1622), 0.0, 1.0);
    float _1735 = _1732 * _1732;
    float3 _1765 = fma(_1270 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1875.y)) + (frame.sh[2].xyz * _1875.z)) + (frame.sh[3].xyz * _1875.x)) + (((((frame.sh[4].xyz * (_1875.x * _1875.y)) + (frame.sh[5].xyz * (_1875.y * _1875.z))) + (frame.sh[6].xyz * fma(3.0 * _1875.z, _1875.z, -1.0))) + (frame.sh[7].xyz * (_1875.x * _1875.z))) + (frame.sh[8].xyz * fma(_1875.x, _1875.x, -(_1875.y * _1875.y)))), float3(0.0)), fast::max(float3(_1279), ((((((_1270 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1279) + ((_1270 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1279) + ((_1270 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1279), (facet_environment.sample(facet_environmentSmplr, reflect(-_934, _1875), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1425.xxx, _1425.yyy, float3(0.039999999105930328369140625)) * _1444)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1360 + _1279)) - 1.0) + _1279, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1735 * _1735) * _1732))) * (((_1667 * _1667) * 0.3183098733425140380859375) * (0.5 / fma(_1543, sqrt(fma(_1360 * _1360, _1705, _1699)), _1360 * sqrt(fma(_1543 * _1543, _1705, _1699))))), _1444, _1270 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1543), float3(65504.0));
    out.fragColor = float4(_1765, 1.0);
    return out;
}

