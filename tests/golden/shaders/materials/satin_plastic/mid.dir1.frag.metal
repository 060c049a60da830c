#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _650 = normalize(half3(in.v_normal));
    float3 _654 = fast::normalize(in.v_toEye);
    half _806 = max(dot(_650, half3(_654)), half(9.9999997473787516355514526367188e-05));
    half3 _810 = reflect(-half3(_654), _650);
    float4 _839 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_806, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _858 = facet_environment.sample(facet_environmentSmplr, float3(_810), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _935 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _892 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_806, _935)), level(0.0));
    half3 _942 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1317 = half4(_892);
    half _905 = _1317.z;
    half _907 = fma(half(-float(max(_942.x, max(_942.y, _942.z)))), _905, half(1.0));
    half _951 = _935 * _935;
    float4 _966 = facet_environment.sample(facet_environmentSmplr, float3(_810), level(_935 * (half(4.0) * (half(2.0) - _935))));
    half3 _710 = half4(frame.lightDirection).xyz;
    half3 _722 = half4(frame.lightColor).xyz;
    half3 _1079 = normalize(half3(_654) + _710);
    half _1021 = clamp(dot(_650, _710), half(0.0), half(1.0));
    half _1025 = clamp(dot(_650, _1079), half(0.0), half(1.0));
    half4 _1148 = half4(cross(_650, _1079), half(params.facet_alpha) * _1025) * half(64.0);
    half _1117 = _1021 + _806;
    half _1125 = half(6.283185482025146484375) * max(mix((half(2.0) * _1021) * _806, _1117, half(params.facet_alpha)), half(0.000244140625));
    half _1127 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1148, _1148) * _1125);
    half _1181 = half(8192.0) * fma(half(-float(_1021)), _806, _1117);
    half _1185 = half(1.0) / (_951 * _1181);
    half3 _1214 = fma(half4(_966).xyz, _942 * _905, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_858).xyz * mix(half4(_839).xxx, half4(_839).yyy, half3(float3(params.facet_f0)))) * _907) + min(fma(half3(float3(params.facet_f0)) * min(_1127 * (_1127 * _1125), half(65504.0)), (_722 * _1021) * _907, (_942 * ((((fma(_1185, _1181, half(2.0)) * pow(max(fma(half(-float(_1025)), _1025, half(1.0)), half(0.0)), half(0.5) * (_1185 * _1181))) * half(0.15915493667125701904296875)) * (_1021 * (_1185 * (half(2048.0) * _951)))) * half4(_892).w)) * _722), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1214, half(1.0)));
    return out;
}

