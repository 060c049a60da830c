#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float tiling;
    float roughness;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
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

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _329 = fast::normalize(in.v_toEye);
    float4 _432 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _436 = (half4(_432).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _654;
    do
    {
        half3 _449 = half4(in.v_tangent).xyz;
        if (float(dot(_449, _449)) == 0.0)
        {
            _654 = normalize(half3(in.v_normal));
            break;
        }
        _654 = normalize(((_449 * _436.x) + ((cross(half3(in.v_normal), _449) * half(in.v_tangent.w)) * _436.y)) + (half3(in.v_normal) * _436.z));
        break;
    } while(false);
    float4 _559 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_654, half3(_329)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _588 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_329), _654)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_588).xyz * (mix(half4(_559).xxx, half4(_559).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_559).y) - half(1.0)))))), half(1.0)));
    return out;
}

