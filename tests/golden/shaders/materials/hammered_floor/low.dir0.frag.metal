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
    float3 _350 = fast::normalize(in.v_toEye);
    float4 _460 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _464 = (half4(_460).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _750;
    do
    {
        half3 _477 = half4(in.v_tangent).xyz;
        if (float(dot(_477, _477)) == 0.0)
        {
            _750 = normalize(half3(in.v_normal));
            break;
        }
        _750 = normalize(((_477 * _464.x) + ((cross(half3(in.v_normal), _477) * half(in.v_tangent.w)) * _464.y)) + (half3(in.v_normal) * _464.z));
        break;
    } while(false);
    half _513 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _523 = dfdx(float3(_750));
    float3 _525 = dfdy(float3(_750));
    half _536 = _513 * _513;
    half _613 = clamp(half(sqrt(sqrt(fast::min(fma(float(_536), float(_536), fast::min((dot(_523, _523) + dot(_525, _525)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    float4 _620 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_750, half3(_350)), half(9.9999997473787516355514526367188e-05)), _613)), level(0.0));
    float4 _639 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_350), _750)), level(_613 * (half(4.0) * (half(2.0) - _613))));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_639).xyz * mix(half4(_620).xxx, half4(_620).yyy, half3(float3(params.facet_f0)))), half(1.0)));
    return out;
}

