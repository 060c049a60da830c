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
    float3 _917 = fast::normalize(in.v_toEye);
    float2 _1036 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1039 = facet_material_albedo.sample(facet_material_albedoSmplr, _1036);
    float4 _1049 = facet_material_relief.sample(facet_material_reliefSmplr, _1036);
    float3 _1053 = (_1049.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1059 = fract(_1036 * 4.0);
    float _1061 = _1059.x;
    float _1068 = _1059.y;
    float3 _1849;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1849 = fast::normalize(in.v_normal);
            break;
        }
        _1849 = fast::normalize(((in.v_tangent.xyz * _1053.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1053.y)) + (in.v_normal * _1053.z));
        break;
    } while(false);
    float3 _1253 = fast::clamp(_1039.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1262 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1061, 1.0 - _1061), fast::min(_1068, 1.0 - _1068)))), 0.0, 1.0);
    float _1343 = fast::max(dot(_1849, _917), 9.9999997473787516355514526367188e-05);
    float4 _1408 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1343, params.facet_perceptualRoughness), level(0.0));
    float3 _1427 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1408.y) - 1.0));
    float3 _1610 = fast::normalize(_917 + frame.lightDirection.xyz);
    float _1531 = fast::clamp(dot(_1849, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1648 = cross(_1849, _1610);
    float _1651 = fast::clamp(dot(_1849, _1610), 0.0, 1.0) * params.facet_alpha;
    float _1660 = params.facet_alpha / fma(_1651, _1651, dot(_1648, _1648));
    float _1673 = params.facet_alpha * params.facet_alpha;
    float _1679 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1706 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1610), 0.0, 1.0);
    float _1709 = _1706 * _1706;
    float3 _1739 = fma(_1253 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1849.y)) + (frame.sh[2].xyz * _1849.z)) + (frame.sh[3].xyz * _1849.x)) + (((((frame.sh[4].xyz * (_1849.x * _1849.y)) + (frame.sh[5].xyz * (_1849.y * _1849.z))) + (frame.sh[6].xyz * fma(3.0 * _1849.z, _1849.z, -1.0))) + (frame.sh[7].xyz * (_1849.x * _1849.z))) + (frame.sh[8].xyz * fma(_1849.x, _1849.x, -(_1849.y * _1849.y)))), float3(0.0)), fast::max(float3(_1262), ((((((_1253 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1262) + ((_1253 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1262) + ((_1253 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1262), (facet_environment.sample(facet_environmentSmplr, reflect(-_917, _1849), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1408.xxx, _1408.yyy, float3(0.039999999105930328369140625)) * _1427)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1343 + _1262)) - 1.0) + _1262, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1709 * _1709) * _1706))) * (((_1660 * _1660) * 0.3183098733425140380859375) * (0.5 / fma(_1531, sqrt(fma(_1343 * _1343, _1679, _1673)), _1343 * sqrt(fma(_1531 * _1531, _1679, _1673))))), _1427, _1253 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1531), float3(65504.0));
    out.fragColor = float4(_1739, 1.0);
    return out;
}

