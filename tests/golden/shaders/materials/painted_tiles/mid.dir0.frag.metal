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
    half3 _593 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _633 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _636 = facet_material_albedo.sample(facet_material_albedoSmplr, _633);
    float4 _646 = facet_material_relief.sample(facet_material_reliefSmplr, _633);
    half3 _650 = (half4(_646).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _656 = fract(_633 * 4.0);
    float _658 = _656.x;
    float _665 = _656.y;
    half3 _1036;
    do
    {
        half3 _690 = half4(in.v_tangent).xyz;
        if (float(dot(_690, _690)) == 0.0)
        {
            _1036 = normalize(half3(in.v_normal));
            break;
        }
        _1036 = normalize(((_690 * _650.x) + ((cross(half3(in.v_normal), _690) * half(in.v_tangent.w)) * _650.y)) + (half3(in.v_normal) * _650.z));
        break;
    } while(false);
    half3 _733 = clamp(half4(_636).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _742 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_658, 1.0 - _658), fast::min(_665, 1.0 - _665))))), half(0.0), half(1.0));
    float4 _900 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1036, _593), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _929 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_593, _1036)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    out.fragColor = float4(half4(fma(_733 * half3(in.v_diffuseLight), max(half3(_742), ((((((_733 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _742) + ((_733 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _742) + ((_733 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _742), _733 * half3(in.v_directDiffuse)) + ((half4(_929).xyz * (mix(half4(_900).xxx, half4(_900).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_900).y) - half(1.0)))))) * _742), half(1.0)));
    return out;
}

