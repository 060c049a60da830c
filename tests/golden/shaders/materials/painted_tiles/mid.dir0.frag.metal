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
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _483 = fast::normalize(in.v_toEye);
    float2 _606 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _609 = facet_material_albedo.sample(facet_material_albedoSmplr, _606);
    float4 _619 = facet_material_relief.sample(facet_material_reliefSmplr, _606);
    half3 _623 = (half4(_619).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _629 = fract(_606 * 4.0);
    float _631 = _629.x;
    float _638 = _629.y;
    half3 _1006;
    do
    {
        half3 _663 = half4(in.v_tangent).xyz;
        if (float(dot(_663, _663)) == 0.0)
        {
            _1006 = normalize(half3(in.v_normal));
            break;
        }
        _1006 = normalize(((_663 * _623.x) + ((cross(half3(in.v_normal), _663) * half(in.v_tangent.w)) * _623.y)) + (half3(in.v_normal) * _623.z));
        break;
    } while(false);
    half3 _706 = clamp(half4(_609).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _715 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_631, 1.0 - _631), fast::min(_638, 1.0 - _638))))), half(0.0), half(1.0));
    float4 _873 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1006, half3(_483)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _899 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_483), _1006)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(_706 * half3(in.v_diffuseLight), max(half3(_715), ((((((_706 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _715) + ((_706 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _715) + ((_706 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _715), _706 * half3(in.v_directDiffuse)) + ((half4(_899).xyz * (mix(half4(_873).xxx, half4(_873).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_873).y) - half(1.0)))))) * _715), half(1.0)));
    return out;
}

