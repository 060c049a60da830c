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
    float2 _750 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _753 = facet_material_albedo.sample(facet_material_albedoSmplr, _750);
    float4 _763 = facet_material_relief.sample(facet_material_reliefSmplr, _750);
    half3 _767 = (half4(_763).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _773 = fract(_750 * 4.0);
    float _775 = _773.x;
    float _782 = _773.y;
    half3 _1289;
    do
    {
        half3 _807 = half4(in.v_tangent).xyz;
        if (float(dot(_807, _807)) == 0.0)
        {
            _1289 = normalize(half3(in.v_normal));
            break;
        }
        _1289 = normalize(((_807 * _767.x) + ((cross(half3(in.v_normal), _807) * half(in.v_tangent.w)) * _767.y)) + (half3(in.v_normal) * _767.z));
        break;
    } while(false);
    half3 _944 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1289.y)) + (half4(frame.sh[2]).xyz * _1289.z)) + (half4(frame.sh[3]).xyz * _1289.x)) + (((((half4(frame.sh[4]).xyz * (_1289.x * _1289.y)) + (half4(frame.sh[5]).xyz * (_1289.y * _1289.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1289.z, _1289.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1289.x * _1289.z))) + (half4(frame.sh[8]).xyz * fma(_1289.x, _1289.x, half(-float(_1289.y * _1289.y))))), half3(float3(0.0)));
    half3 _967 = clamp(half4(_753).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _976 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_775, 1.0 - _775), fast::min(_782, 1.0 - _782))))), half(0.0), half(1.0));
    half _1057 = max(dot(_1289, half3(_652)), half(9.9999997473787516355514526367188e-05));
    float4 _1122 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1057, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1148 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_652), _1289)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1189 = fma(_967 * _944, max(half3(_976), ((((((_967 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _976) + ((_967 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _976) + ((_967 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _976), (half4(_1148).xyz * (mix(half4(_1122).xxx, half4(_1122).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1122).y) - half(1.0)))))) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1057 + _976)) - half(1.0)) + _976, half(0.0), half(1.0)));
    out.fragColor = float4(half4(_1189, half(1.0)));
    return out;
}

