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

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    half3 _599 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _639 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _642 = facet_material_albedo.sample(facet_material_albedoSmplr, _639);
    float4 _652 = facet_material_relief.sample(facet_material_reliefSmplr, _639);
    half3 _656 = (half4(_652).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _662 = fract(_639 * 4.0);
    float _664 = _662.x;
    float _671 = _662.y;
    half3 _1046;
    do
    {
        half3 _696 = half4(in.v_tangent).xyz;
        if (float(dot(_696, _696)) == 0.0)
        {
            _1046 = normalize(half3(in.v_normal));
            break;
        }
        _1046 = normalize(((_696 * _656.x) + ((cross(half3(in.v_normal), _696) * half(in.v_tangent.w)) * _656.y)) + (half3(in.v_normal) * _656.z));
        break;
    } while(false);
    half3 _739 = clamp(half4(_642).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _748 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_664, 1.0 - _664), fast::min(_671, 1.0 - _671))))), half(0.0), half(1.0));
    half4 _896 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _898 = _896.x;
    half2 _916 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_898 * _898, exp2(half(-9.27999973297119140625) * max(dot(_1046, _599), half(9.9999997473787516355514526367188e-05)))), _898, _896.y)) + _896.zw;
    float4 _934 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_599, _1046)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    out.fragColor = float4(half4(fma(_739 * half3(in.v_diffuseLight), max(half3(_748), ((((((_739 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _748) + ((_739 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _748) + ((_739 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _748), _739 * half3(in.v_directDiffuse)) + ((half4(_934).xyz * ((half3(float3(0.039999999105930328369140625)) * _916.x) + half3(_916.y))) * _748), half(1.0)));
    return out;
}

