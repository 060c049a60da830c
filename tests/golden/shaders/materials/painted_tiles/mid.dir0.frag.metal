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
    float3 _435 = fast::normalize(in.v_toEye);
    float2 _547 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _550 = facet_material_albedo.sample(facet_material_albedoSmplr, _547);
    float4 _560 = facet_material_relief.sample(facet_material_reliefSmplr, _547);
    half3 _564 = (half4(_560).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _570 = fract(_547 * 4.0);
    float _572 = _570.x;
    float _579 = _570.y;
    half3 _878;
    do
    {
        half3 _604 = half4(in.v_tangent).xyz;
        if (float(dot(_604, _604)) == 0.0)
        {
            _878 = normalize(half3(in.v_normal));
            break;
        }
        _878 = normalize(((_604 * _564.x) + ((cross(half3(in.v_normal), _604) * half(in.v_tangent.w)) * _564.y)) + (half3(in.v_normal) * _564.z));
        break;
    } while(false);
    half _653 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_572, 1.0 - _572), fast::min(_579, 1.0 - _579))))), half(0.0), half(1.0));
    float4 _753 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_878, half3(_435)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _779 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_435), _878)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4((((clamp(half4(_550).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0)) * half3(in.v_diffuseLight)) * _653) + ((half4(_779).xyz * (mix(half4(_753).xxx, half4(_753).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_753).y) - half(1.0)))))) * _653), half(1.0)));
    return out;
}

