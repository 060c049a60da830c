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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _561 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _601 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _604 = facet_material_albedo.sample(facet_material_albedoSmplr, _601);
    float4 _614 = facet_material_relief.sample(facet_material_reliefSmplr, _601);
    half3 _618 = (half4(_614).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _624 = fract(_601 * 4.0);
    float _626 = _624.x;
    float _633 = _624.y;
    half3 _976;
    do
    {
        half3 _658 = half4(in.v_tangent).xyz;
        if (float(dot(_658, _658)) == 0.0)
        {
            _976 = normalize(half3(in.v_normal));
            break;
        }
        _976 = normalize(((_658 * _618.x) + ((cross(half3(in.v_normal), _658) * half(in.v_tangent.w)) * _618.y)) + (half3(in.v_normal) * _618.z));
        break;
    } while(false);
    half3 _701 = clamp(half4(_604).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _710 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_626, 1.0 - _626), fast::min(_633, 1.0 - _633))))), half(0.0), half(1.0));
    float4 _862 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_976, _561), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _814 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_561, _976)), level(params.facet_environmentLod));
    half3 _885 = fma(_701 * half3(in.v_diffuseLight), max(half3(_710), ((((((_701 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _710) + ((_701 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _710) + ((_701 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _710), _701 * half3(in.v_directDiffuse)) + ((half4(_814).xyz * mix(half4(_862).xxx, half4(_862).yyy, half3(float3(0.039999999105930328369140625)))) * _710);
    out.fragColor = float4(half4(_885, half(1.0)));
    return out;
}

