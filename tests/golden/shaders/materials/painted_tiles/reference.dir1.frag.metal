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
    float3 _915 = fast::normalize(in.v_toEye);
    float2 _1034 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1037 = facet_material_albedo.sample(facet_material_albedoSmplr, _1034);
    float4 _1047 = facet_material_relief.sample(facet_material_reliefSmplr, _1034);
    float3 _1051 = (_1047.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1057 = fract(_1034 * 4.0);
    float _1059 = _1057.x;
    float _1066 = _1057.y;
    float3 _1845;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1845 = fast::normalize(in.v_normal);
            break;
        }
        _1845 = fast::normalize(((in.v_tangent.xyz * _1051.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1051.y)) + (in.v_normal * _1051.z));
        break;
    } while(false);
    float3 _1251 = fast::clamp(_1037.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1260 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1059, 1.0 - _1059), fast::min(_1066, 1.0 - _1066)))), 0.0, 1.0);
    float _1341 = fast::max(dot(_1845, _915), 9.9999997473787516355514526367188e-05);
    float4 _1406 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1341, params.facet_perceptualRoughness), level(0.0));
    float3 _1425 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1406.y) - 1.0));
    float3 _1606 = fast::normalize(_915 + frame.lightDirection.xyz);
    float _1527 = fast::clamp(dot(_1845, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1644 = cross(_1845, _1606);
    float _1647 = fast::clamp(dot(_1845, _1606), 0.0, 1.0) * params.facet_alpha;
    float _1656 = params.facet_alpha / fma(_1647, _1647, dot(_1644, _1644));
    float _1669 = params.facet_alpha * params.facet_alpha;
    float _1675 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1702 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1606), 0.0, 1.0);
    float _1705 = _1702 * _1702;
    float3 _1735 = fma(_1251 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1845.y)) + (frame.sh[2].xyz * _1845.z)) + (frame.sh[3].xyz * _1845.x)) + (((((frame.sh[4].xyz * (_1845.x * _1845.y)) + (frame.sh[5].xyz * (_1845.y * _1845.z))) + (frame.sh[6].xyz * fma(3.0 * _1845.z, _1845.z, -1.0))) + (frame.sh[7].xyz * (_1845.x * _1845.z))) + (frame.sh[8].xyz * fma(_1845.x, _1845.x, -(_1845.y * _1845.y)))), float3(0.0)), fast::max(float3(_1260), ((((((_1251 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1260) + ((_1251 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1260) + ((_1251 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1260), (facet_environment.sample(facet_environmentSmplr, reflect(-_915, _1845), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1406.xxx, _1406.yyy, float3(0.039999999105930328369140625)) * _1425)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1341 + _1260)) - 1.0) + _1260, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1705 * _1705) * _1702))) * (((_1656 * _1656) * 0.3183098733425140380859375) * (0.5 / fma(_1527, sqrt(fma(_1341 * _1341, _1675, _1669)), _1341 * sqrt(fma(_1527 * _1527, _1675, _1669))))), _1425, _1251 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1527), float3(65504.0));
    out.fragColor = float4(_1735, 1.0);
    return out;
}

