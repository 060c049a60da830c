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
    half3 _568 = normalize(half3(in.v_normal));
    float3 _572 = fast::normalize(in.v_toEye);
    half _735 = max(dot(_568, half3(_572)), half(9.9999997473787516355514526367188e-05));
    half3 _739 = reflect(-half3(_572), _568);
    float4 _774 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_735, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _793 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_774).y) - half(1.0)));
    float4 _803 = facet_environment.sample(facet_environmentSmplr, float3(_739), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _620 = half4(frame.lightDirection).xyz;
    half3 _910 = normalize(half3(_572) + _620);
    half _861 = clamp(dot(_568, _620), half(0.0), half(1.0));
    half4 _979 = half4(cross(_568, _910), half(params.facet_alpha) * clamp(dot(_568, _910), half(0.0), half(1.0))) * half(64.0);
    half _956 = half(6.283185482025146484375) * max(mix((half(2.0) * _861) * _735, _861 + _735, half(params.facet_alpha)), half(0.000244140625));
    half _958 = (half(4096.0) * half(params.facet_alpha)) / (dot(_979, _979) * _956);
    half _1026 = half(1.0) - _735;
    half _1029 = _1026 * _1026;
    half _1046 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1056 = facet_environment.sample(facet_environmentSmplr, float3(_739), level(_1046 * (half(4.0) * (half(2.0) - _1046))));
    half3 _1020 = mix(fma(half4(_803).xyz, mix(half4(_774).xxx, half4(_774).yyy, half3(float3(params.facet_f0))) * _793, min(((half3(float3(params.facet_f0)) * min(_958 * (_958 * _956), half(65504.0))) * _793) * (half4(frame.lightColor).xyz * _861), half3(float3(65504.0)))), half4(_1056).xyz, half3(fma(half(0.959999978542327880859375), (_1029 * _1029) * _1026, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1020, half(1.0)));
    return out;
}

