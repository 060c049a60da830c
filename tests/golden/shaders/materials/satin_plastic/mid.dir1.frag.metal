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
    half3 _654 = normalize(half3(in.v_normal));
    float3 _658 = fast::normalize(in.v_toEye);
    half _812 = max(dot(_654, half3(_658)), half(9.9999997473787516355514526367188e-05));
    half3 _816 = reflect(-half3(_658), _654);
    float4 _851 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_812, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _870 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_851).y) - half(1.0)));
    float4 _877 = facet_environment.sample(facet_environmentSmplr, float3(_816), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _954 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _911 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_812, _954)), level(0.0));
    half3 _961 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1330 = half4(_911);
    half _924 = _1330.z;
    half _926 = fma(half(-float(max(_961.x, max(_961.y, _961.z)))), _924, half(1.0));
    half _970 = _954 * _954;
    float4 _982 = facet_environment.sample(facet_environmentSmplr, float3(_816), level(_954 * half(4.0)));
    half3 _714 = half4(frame.lightDirection).xyz;
    half3 _726 = half4(frame.lightColor).xyz;
    half3 _1098 = normalize(half3(_658) + _714);
    half _1037 = clamp(dot(_654, _714), half(0.0), half(1.0));
    half _1041 = clamp(dot(_654, _1098), half(0.0), half(1.0));
    half3 _1125 = cross(_654, _1098);
    half _1128 = _1041 * half(params.facet_alpha);
    half _1142 = _1037 + _812;
    half _1145 = max(mix((half(2.0) * _1037) * _812, _1142, half(params.facet_alpha)), half(0.000244140625));
    half _1152 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1128, _1128, dot(_1125, _1125)) * (half(6433.98193359375) * _1145));
    half _1189 = half(8192.0) * fma(half(-float(_1037)), _812, _1142);
    half _1193 = half(1.0) / (_970 * _1189);
    half3 _1222 = fma(half4(_982).xyz, _961 * _924, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_877).xyz * (mix(half4(_851).xxx, half4(_851).yyy, half3(float3(params.facet_f0))) * _870)) * _926) + min(fma((half3(float3(params.facet_f0)) * min(_1152 * (_1152 * (half(6.283185482025146484375) * _1145)), half(65504.0))) * _870, (_726 * _1037) * _926, (_961 * ((((fma(_1193, _1189, half(2.0)) * pow(max(fma(half(-float(_1041)), _1041, half(1.0)), half(0.0)), half(0.5) * (_1193 * _1189))) * half(0.15915493667125701904296875)) * (_1037 * (_1193 * (half(2048.0) * _970)))) * half4(_911).w)) * _726), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1222, half(1.0)));
    return out;
}

