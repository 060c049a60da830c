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
    float3 _437 = fast::normalize(in.v_toEye);
    float2 _564 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _567 = facet_material_albedo.sample(facet_material_albedoSmplr, _564);
    float4 _577 = facet_material_relief.sample(facet_material_reliefSmplr, _564);
    half3 _581 = (half4(_577).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _587 = fract(_564 * 4.0);
    float _589 = _587.x;
    float _596 = _587.y;
    half3 _912;
    do
    {
        half3 _621 = half4(in.v_tangent).xyz;
        if (float(dot(_621, _621)) == 0.0)
        {
            _912 = normalize(half3(in.v_normal));
            break;
        }
        _912 = normalize(((_621 * _581.x) + ((cross(half3(in.v_normal), _621) * half(in.v_tangent.w)) * _581.y)) + (half3(in.v_normal) * _581.z));
        break;
    } while(false);
    half3 _664 = clamp(half4(_567).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _670 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_589, 1.0 - _589), fast::min(_596, 1.0 - _596))))), half(0.0), half(1.0));
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_912, half3(_437)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _809 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_437), _912)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(_664, half3(in.v_directDiffuse), (_664 * half3(in.v_diffuseLight)) * _670) + ((half4(_809).xyz * (mix(half4(_783).xxx, half4(_783).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_783).y) - half(1.0)))))) * _670), half(1.0)));
    return out;
}

