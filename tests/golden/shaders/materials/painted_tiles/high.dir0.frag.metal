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
    float2 _753 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _756 = facet_material_albedo.sample(facet_material_albedoSmplr, _753);
    float4 _766 = facet_material_relief.sample(facet_material_reliefSmplr, _753);
    half3 _770 = (half4(_766).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _776 = fract(_753 * 4.0);
    float _778 = _776.x;
    float _785 = _776.y;
    half3 _1295;
    do
    {
        half3 _810 = half4(in.v_tangent).xyz;
        if (float(dot(_810, _810)) == 0.0)
        {
            _1295 = normalize(half3(in.v_normal));
            break;
        }
        _1295 = normalize(((_810 * _770.x) + ((cross(half3(in.v_normal), _810) * half(in.v_tangent.w)) * _770.y)) + (half3(in.v_normal) * _770.z));
        break;
    } while(false);
    half3 _947 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1295.y)) + (half4(frame.sh[2]).xyz * _1295.z)) + (half4(frame.sh[3]).xyz * _1295.x)) + (((((half4(frame.sh[4]).xyz * (_1295.x * _1295.y)) + (half4(frame.sh[5]).xyz * (_1295.y * _1295.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1295.z, _1295.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1295.x * _1295.z))) + (half4(frame.sh[8]).xyz * fma(_1295.x, _1295.x, half(-float(_1295.y * _1295.y))))), half3(float3(0.0)));
    half3 _970 = clamp(half4(_756).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _979 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_778, 1.0 - _778), fast::min(_785, 1.0 - _785))))), half(0.0), half(1.0));
    half _1060 = max(dot(_1295, half3(_655)), half(9.9999997473787516355514526367188e-05));
    float4 _1125 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1060, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1154 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_655), _1295)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1195 = fma(_970 * _947, max(half3(_979), ((((((_970 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _979) + ((_970 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _979) + ((_970 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _979), (half4(_1154).xyz * (mix(half4(_1125).xxx, half4(_1125).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1125).y) - half(1.0)))))) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1060 + _979)) - half(1.0)) + _979, half(0.0), half(1.0)));
    out.fragColor = float4(half4(_1195, half(1.0)));
    return out;
}

