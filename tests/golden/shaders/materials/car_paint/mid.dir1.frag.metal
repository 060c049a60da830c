#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
};

struct PunctualLightData
{
    float4 positionFalloff;
    float4 colorIntensity;
    float4 direction;
    float4 spotScaleOffset;
};

struct FrameUniforms
{
    float4x4 viewProjection;
    float4 cameraPosition;
    float4 lightDirection;
    float4 lightColor;
    float4 ambient;
    PunctualLightData punctualLights[4];
    float4 sh[9];
};

struct main0_out
{
    float4 fragColor [[color(0)]];
};

struct main0_in
{
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _573 = normalize(half3(in.v_normal));
    float3 _577 = fast::normalize(in.v_toEye);
    half _740 = max(dot(_573, half3(_577)), half(9.9999997473787516355514526367188e-05));
    half3 _744 = reflect(-half3(_577), _573);
    float4 _779 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_740, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _798 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_779).y) - half(1.0)));
    float4 _808 = facet_environment.sample(facet_environmentSmplr, float3(_744), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _625 = half4(frame.lightDirection).xyz;
    half3 _915 = normalize(half3(_577) + _625);
    half _866 = clamp(dot(_573, _625), half(0.0), half(1.0));
    half4 _984 = half4(cross(_573, _915), half(params.facet_alpha) * clamp(dot(_573, _915), half(0.0), half(1.0))) * half(64.0);
    half _961 = half(6.283185482025146484375) * max(mix((half(2.0) * _866) * _740, _866 + _740, half(params.facet_alpha)), half(0.000244140625));
    half _963 = (half(4096.0) * half(params.facet_alpha)) / (dot(_984, _984) * _961);
    half _1030 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1036 = half(1.0) - _740;
    half _1039 = _1036 * _1036;
    half _1055 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1065 = facet_environment.sample(facet_environmentSmplr, float3(_744), level(_1055 * (half(4.0) * (half(2.0) - _1055))));
    half3 _1025 = mix(fma(half4(_808).xyz, mix(half4(_779).xxx, half4(_779).yyy, half3(float3(params.facet_f0))) * _798, min(((half3(float3(params.facet_f0)) * min(_963 * (_963 * _961), half(65504.0))) * _798) * (half4(frame.lightColor).xyz * _866), half3(float3(65504.0)))), half4(_1065).xyz, half3(fma(half(0.039999999105930328369140625), _1030, (half(0.959999978542327880859375) * _1030) * ((_1039 * _1039) * _1036))));
    out.fragColor = float4(half4(_1025, half(1.0)));
    return out;
}

