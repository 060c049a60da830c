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

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    half3 _584 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _624 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _627 = facet_material_albedo.sample(facet_material_albedoSmplr, _624);
    float4 _637 = facet_material_relief.sample(facet_material_reliefSmplr, _624);
    half3 _641 = (half4(_637).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _647 = fract(_624 * 4.0);
    float _649 = _647.x;
    float _656 = _647.y;
    half3 _1021;
    do
    {
        half3 _681 = half4(in.v_tangent).xyz;
        if (float(dot(_681, _681)) == 0.0)
        {
            _1021 = normalize(half3(in.v_normal));
            break;
        }
        _1021 = normalize(((_681 * _641.x) + ((cross(half3(in.v_normal), _681) * half(in.v_tangent.w)) * _641.y)) + (half3(in.v_normal) * _641.z));
        break;
    } while(false);
    half3 _724 = clamp(half4(_627).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _733 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_649, 1.0 - _649), fast::min(_656, 1.0 - _656))))), half(0.0), half(1.0));
    half4 _882 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _884 = _882.x;
    half2 _902 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_884 * _884, exp2(half(-9.27999973297119140625) * max(dot(_1021, _584), half(9.9999997473787516355514526367188e-05)))), _884, _882.y)) + _882.zw;
    float4 _833 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_584, _1021)), level(params.facet_environmentLod));
    out.fragColor = float4(half4(fma(_724 * half3(in.v_diffuseLight), max(half3(_733), ((((((_724 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _733) + ((_724 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _733) + ((_724 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _733), _724 * half3(in.v_directDiffuse)) + ((half4(_833).xyz * ((half3(float3(0.039999999105930328369140625)) * _902.x) + half3(_902.y))) * _733), half(1.0)));
    return out;
}

