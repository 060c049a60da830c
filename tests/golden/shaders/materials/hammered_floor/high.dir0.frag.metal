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
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _373 = fast::normalize(in.v_toEye);
    float4 _475 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _479 = (half4(_475).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _781;
    do
    {
        half3 _492 = half4(in.v_tangent).xyz;
        if (float(dot(_492, _492)) == 0.0)
        {
            _781 = normalize(half3(in.v_normal));
            break;
        }
        _781 = normalize(((_492 * _479.x) + ((cross(half3(in.v_normal), _492) * half(in.v_tangent.w)) * _479.y)) + (half3(in.v_normal) * _479.z));
        break;
    } while(false);
    half _528 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _538 = dfdx(float3(_781));
    float3 _540 = dfdy(float3(_781));
    half _551 = _528 * _528;
    float4 _568 = facet_irradiance.sample(facet_irradianceSmplr, float3(_781), level(0.0));
    half _644 = clamp(half(sqrt(sqrt(fast::min(fma(float(_551), float(_551), fast::min((dot(_538, _538) + dot(_540, _540)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    float4 _651 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_781, half3(_373)), half(9.9999997473787516355514526367188e-05)), _644)), level(0.0));
    float4 _670 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_373), _781)), level(_644 * (half(4.0) * (half(2.0) - _644))));
    half3 _679 = fma(half3(float3(params.facet_diffuseColor)), half4(_568).xyz, half4(_670).xyz * mix(half4(_651).xxx, half4(_651).yyy, half3(float3(params.facet_f0))));
    out.fragColor = float4(half4(_679, half(1.0)));
    return out;
}

