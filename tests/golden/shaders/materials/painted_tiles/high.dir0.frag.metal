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
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _473 = fast::normalize(in.v_toEye);
    float2 _580 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _583 = facet_material_albedo.sample(facet_material_albedoSmplr, _580);
    float4 _593 = facet_material_relief.sample(facet_material_reliefSmplr, _580);
    half3 _597 = (half4(_593).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _603 = fract(_580 * 4.0);
    float _605 = _603.x;
    float _612 = _603.y;
    half3 _952;
    do
    {
        half3 _637 = half4(in.v_tangent).xyz;
        if (float(dot(_637, _637)) == 0.0)
        {
            _952 = normalize(half3(in.v_normal));
            break;
        }
        _952 = normalize(((_637 * _597.x) + ((cross(half3(in.v_normal), _637) * half(in.v_tangent.w)) * _597.y)) + (half3(in.v_normal) * _597.z));
        break;
    } while(false);
    float4 _673 = facet_irradiance.sample(facet_irradianceSmplr, float3(_952), level(0.0));
    half3 _697 = clamp(half4(_583).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _706 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_605, 1.0 - _605), fast::min(_612, 1.0 - _612))))), half(0.0), half(1.0));
    float4 _845 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_952, half3(_473)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _798 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_473), _952)), level(params.facet_environmentLod));
    half3 _868 = fma(_697 * half4(_673).xyz, max(half3(_706), ((((((_697 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _706) + ((_697 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _706) + ((_697 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _706), (half4(_798).xyz * mix(half4(_845).xxx, half4(_845).yyy, half3(float3(0.039999999105930328369140625)))) * _706);
    out.fragColor = float4(half4(_868, half(1.0)));
    return out;
}

