#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _379 = normalize(half3(in.v_normal));
    float3 _383 = fast::normalize(in.v_toEye);
    half3 _481 = half4(in.v_tangent).xyz;
    half _534 = max(dot(_379, half3(_383)), half(9.9999997473787516355514526367188e-05));
    half _643 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _765;
    if (float(_643) >= 0.0)
    {
        _765 = _481;
    }
    else
    {
        _765 = cross(_379, _481);
    }
    half _595 = dot(_765, half3(_383));
    half _602 = min(abs(_643) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _607 = fma(half(-float(_602)), half(1.0) - _534, half(1.0));
    half _610 = _602 * _595;
    float4 _650 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_534, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _676 = facet_environment.sample(facet_environmentSmplr, float3(((((_379 * _607) + (_765 * _610)) * (half(512.0) * fma(_607, _534, _610 * _595))) - (half3(_383) * (half(256.0) * fma(_607, _607, _610 * _610))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _559 = half4(_676).xyz * (mix(half4(_650).xxx, half4(_650).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_650).y) - half(1.0)))));
    out.fragColor = float4(half4(_559, half(1.0)));
    return out;
}

