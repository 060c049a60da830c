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
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _488 = fast::normalize(in.v_toEye);
    float2 _595 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _598 = facet_material_albedo.sample(facet_material_albedoSmplr, _595);
    float4 _608 = facet_material_relief.sample(facet_material_reliefSmplr, _595);
    half3 _612 = (half4(_608).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _618 = fract(_595 * 4.0);
    float _620 = _618.x;
    float _627 = _618.y;
    half3 _977;
    do
    {
        half3 _652 = half4(in.v_tangent).xyz;
        if (float(dot(_652, _652)) == 0.0)
        {
            _977 = normalize(half3(in.v_normal));
            break;
        }
        _977 = normalize(((_652 * _612.x) + ((cross(half3(in.v_normal), _652) * half(in.v_tangent.w)) * _612.y)) + (half3(in.v_normal) * _612.z));
        break;
    } while(false);
    float4 _688 = facet_irradiance.sample(facet_irradianceSmplr, float3(_977), level(0.0));
    half3 _712 = clamp(half4(_598).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _721 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_620, 1.0 - _620), fast::min(_627, 1.0 - _627))))), half(0.0), half(1.0));
    float4 _859 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_977, half3(_488)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _878 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_488), _977)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _893 = fma(_712 * half4(_688).xyz, max(half3(_721), ((((((_712 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _721) + ((_712 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _721) + ((_712 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _721), (half4(_878).xyz * mix(half4(_859).xxx, half4(_859).yyy, half3(float3(0.039999999105930328369140625)))) * _721);
    out.fragColor = float4(half4(_893, half(1.0)));
    return out;
}

