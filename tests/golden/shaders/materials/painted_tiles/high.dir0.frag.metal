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
    float3 _507 = fast::normalize(in.v_toEye);
    float2 _594 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _597 = facet_material_albedo.sample(facet_material_albedoSmplr, _594);
    float4 _607 = facet_material_relief.sample(facet_material_reliefSmplr, _594);
    half3 _611 = (half4(_607).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1004;
    do
    {
        half3 _624 = half4(in.v_tangent).xyz;
        if (float(dot(_624, _624)) == 0.0)
        {
            _1004 = normalize(half3(in.v_normal));
            break;
        }
        _1004 = normalize(((_624 * _611.x) + ((cross(half3(in.v_normal), _624) * half(in.v_tangent.w)) * _611.y)) + (half3(in.v_normal) * _611.z));
        break;
    } while(false);
    half3 _761 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1004.y)) + (half4(frame.sh[2]).xyz * _1004.z)) + (half4(frame.sh[3]).xyz * _1004.x)) + (((((half4(frame.sh[4]).xyz * (_1004.x * _1004.y)) + (half4(frame.sh[5]).xyz * (_1004.y * _1004.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1004.z, _1004.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1004.x * _1004.z))) + (half4(frame.sh[8]).xyz * fma(_1004.x, _1004.x, half(-float(_1004.y * _1004.y))))), half3(float3(0.0)));
    float4 _882 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1004, half3(_507)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _908 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_507), _1004)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(clamp(half4(_597).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), _761, half4(_908).xyz * (mix(half4(_882).xxx, half4(_882).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_882).y) - half(1.0)))))), half(1.0)));
    return out;
}

