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
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    half3 _450 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _478 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _482 = (half4(_478).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _767;
    do
    {
        half3 _495 = half4(in.v_tangent).xyz;
        if (float(dot(_495, _495)) == 0.0)
        {
            _767 = normalize(half3(in.v_normal));
            break;
        }
        _767 = normalize(((_495 * _482.x) + ((cross(half3(in.v_normal), _495) * half(in.v_tangent.w)) * _482.y)) + (half3(in.v_normal) * _482.z));
        break;
    } while(false);
    half _531 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _541 = dfdx(float3(_767));
    float3 _543 = dfdy(float3(_767));
    half _554 = _531 * _531;
    half _630 = clamp(half(sqrt(sqrt(fast::min(fma(float(_554), float(_554), fast::min((dot(_541, _541) + dot(_543, _543)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    float4 _637 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_767, _450), half(9.9999997473787516355514526367188e-05)), _630)), level(0.0));
    float4 _656 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_450, _767)), level(_630 * (half(4.0) * (half(2.0) - _630))));
    half3 _665 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_656).xyz * mix(half4(_637).xxx, half4(_637).yyy, half3(float3(params.facet_f0))));
    out.fragColor = float4(half4(_665, half(1.0)));
    return out;
}

