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
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _373 = fast::normalize(in.v_toEye);
    float2 _477 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _480 = facet_material_albedo.sample(facet_material_albedoSmplr, _477);
    float4 _490 = facet_material_relief.sample(facet_material_reliefSmplr, _477);
    half3 _494 = (half4(_490).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _762;
    do
    {
        half3 _507 = half4(in.v_tangent).xyz;
        if (float(dot(_507, _507)) == 0.0)
        {
            _762 = normalize(half3(in.v_normal));
            break;
        }
        _762 = normalize(((_507 * _494.x) + ((cross(half3(in.v_normal), _507) * half(in.v_tangent.w)) * _494.y)) + (half3(in.v_normal) * _494.z));
        break;
    } while(false);
    float4 _649 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_762, half3(_373)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _675 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_373), _762)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(clamp(half4(_480).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_675).xyz * (mix(half4(_649).xxx, half4(_649).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_649).y) - half(1.0)))))), half(1.0)));
    return out;
}

