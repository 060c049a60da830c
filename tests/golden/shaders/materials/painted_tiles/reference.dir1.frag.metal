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
    float3 _930 = fast::normalize(in.v_toEye);
    float2 _1049 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1052 = facet_material_albedo.sample(facet_material_albedoSmplr, _1049);
    float4 _1062 = facet_material_relief.sample(facet_material_reliefSmplr, _1049);
    float3 _1066 = (_1062.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1072 = fract(_1049 * 4.0);
    float _1074 = _1072.x;
    float _1081 = _1072.y;
    float3 _1867;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1867 = fast::normalize(in.v_normal);
            break;
        }
        _1867 = fast::normalize(((in.v_tangent.xyz * _1066.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1066.y)) + (in.v_normal * _1066.z));
        break;
    } while(false);
    float3 _1266 = fast::clamp(_1052.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1275 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1074, 1.0 - _1074), fast::min(_1081, 1.0 - _1081)))), 0.0, 1.0);
    float _1356 = fast::max(dot(_1867, _930), 9.9999997473787516355514526367188e-05);
    float4 _1421 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1356, params.facet_perceptualRoughness), level(0.0));
    float3 _1440 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1421.y) - 1.0));
    float3 _1618 = fast::normalize(_930 + frame.lightDirection.xyz);
    float _1539 = fast::clamp(dot(_1867, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1680 = float4(cross(_1867, _1618), params.facet_alpha * fast::clamp(dot(_1867, _1618), 0.0, 1.0)) * 64.0;
    float _1662 = (4096.0 * params.facet_alpha) / dot(_1680, _1680);
    float _1691 = params.facet_alpha * params.facet_alpha;
    float _1697 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1724 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1618), 0.0, 1.0);
    float _1727 = _1724 * _1724;
    float3 _1757 = fma(_1266 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1867.y)) + (frame.sh[2].xyz * _1867.z)) + (frame.sh[3].xyz * _1867.x)) + (((((frame.sh[4].xyz * (_1867.x * _1867.y)) + (frame.sh[5].xyz * (_1867.y * _1867.z))) + (frame.sh[6].xyz * fma(3.0 * _1867.z, _1867.z, -1.0))) + (frame.sh[7].xyz * (_1867.x * _1867.z))) + (frame.sh[8].xyz * fma(_1867.x, _1867.x, -(_1867.y * _1867.y)))), float3(0.0)), fast::max(float3(_1275), ((((((_1266 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1275) + ((_1266 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1275) + ((_1266 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1275), (facet_environment.sample(facet_environmentSmplr, reflect(-_930, _1867), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1421.xxx, _1421.yyy, float3(0.039999999105930328369140625)) * _1440)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1356 + _1275)) - 1.0) + _1275, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1727 * _1727) * _1724))) * (((_1662 * _1662) * 0.3183098733425140380859375) * (0.5 / fma(_1539, sqrt(fma(_1356 * _1356, _1697, _1691)), _1356 * sqrt(fma(_1539 * _1539, _1697, _1691))))), _1440, _1266 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1539), float3(65504.0));
    out.fragColor = float4(_1757, 1.0);
    return out;
}

