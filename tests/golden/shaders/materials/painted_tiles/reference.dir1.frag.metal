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
    float3 _912 = fast::normalize(in.v_toEye);
    float2 _1031 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1034 = facet_material_albedo.sample(facet_material_albedoSmplr, _1031);
    float4 _1044 = facet_material_relief.sample(facet_material_reliefSmplr, _1031);
    float3 _1048 = (_1044.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1054 = fract(_1031 * 4.0);
    float _1056 = _1054.x;
    float _1063 = _1054.y;
    float3 _1839;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1839 = fast::normalize(in.v_normal);
            break;
        }
        _1839 = fast::normalize(((in.v_tangent.xyz * _1048.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1048.y)) + (in.v_normal * _1048.z));
        break;
    } while(false);
    float3 _1248 = fast::clamp(_1034.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1257 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1056, 1.0 - _1056), fast::min(_1063, 1.0 - _1063)))), 0.0, 1.0);
    float _1338 = fast::max(dot(_1839, _912), 9.9999997473787516355514526367188e-05);
    float4 _1403 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1338, params.facet_perceptualRoughness), level(0.0));
    float3 _1422 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1403.y) - 1.0));
    float3 _1600 = fast::normalize(_912 + frame.lightDirection.xyz);
    float _1521 = fast::clamp(dot(_1839, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1638 = cross(_1839, _1600);
    float _1641 = fast::clamp(dot(_1839, _1600), 0.0, 1.0) * params.facet_alpha;
    float _1650 = params.facet_alpha / fma(_1641, _1641, dot(_1638, _1638));
    float _1663 = params.facet_alpha * params.facet_alpha;
    float _1669 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1696 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1600), 0.0, 1.0);
    float _1699 = _1696 * _1696;
    float3 _1729 = fma(_1248 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1839.y)) + (frame.sh[2].xyz * _1839.z)) + (frame.sh[3].xyz * _1839.x)) + (((((frame.sh[4].xyz * (_1839.x * _1839.y)) + (frame.sh[5].xyz * (_1839.y * _1839.z))) + (frame.sh[6].xyz * fma(3.0 * _1839.z, _1839.z, -1.0))) + (frame.sh[7].xyz * (_1839.x * _1839.z))) + (frame.sh[8].xyz * fma(_1839.x, _1839.x, -(_1839.y * _1839.y)))), float3(0.0)), fast::max(float3(_1257), ((((((_1248 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1257) + ((_1248 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1257) + ((_1248 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1257), (facet_environment.sample(facet_environmentSmplr, reflect(-_912, _1839), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1403.xxx, _1403.yyy, float3(0.039999999105930328369140625)) * _1422)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1338 + _1257)) - 1.0) + _1257, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1699 * _1699) * _1696))) * (((_1650 * _1650) * 0.3183098733425140380859375) * (0.5 / fma(_1521, sqrt(fma(_1338 * _1338, _1669, _1663)), _1338 * sqrt(fma(_1521 * _1521, _1669, _1663))))), _1422, _1248 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1521), float3(65504.0));
    out.fragColor = float4(_1729, 1.0);
    return out;
}

