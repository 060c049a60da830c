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
    float3 _435 = fast::normalize(in.v_toEye);
    float2 _559 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _562 = facet_material_albedo.sample(facet_material_albedoSmplr, _559);
    float4 _572 = facet_material_relief.sample(facet_material_reliefSmplr, _559);
    half3 _576 = (half4(_572).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _582 = fract(_559 * 4.0);
    float _584 = _582.x;
    float _591 = _582.y;
    half3 _906;
    do
    {
        half3 _616 = half4(in.v_tangent).xyz;
        if (float(dot(_616, _616)) == 0.0)
        {
            _906 = normalize(half3(in.v_normal));
            break;
        }
        _906 = normalize(((_616 * _576.x) + ((cross(half3(in.v_normal), _616) * half(in.v_tangent.w)) * _576.y)) + (half3(in.v_normal) * _576.z));
        break;
    } while(false);
    half3 _659 = clamp(half4(_562).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _665 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_584, 1.0 - _584), fast::min(_591, 1.0 - _591))))), half(0.0), half(1.0));
    float4 _777 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_906, half3(_435)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _803 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_435), _906)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(_659, half3(in.v_directDiffuse), (_659 * half3(in.v_diffuseLight)) * _665) + ((half4(_803).xyz * (mix(half4(_777).xxx, half4(_777).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_777).y) - half(1.0)))))) * _665), half(1.0)));
    return out;
}

