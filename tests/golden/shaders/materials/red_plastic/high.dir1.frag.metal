#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _681 = normalize(half3(in.v_normal));
    float3 _685 = fast::normalize(in.v_toEye);
    half _803 = _681.y;
    half _808 = _681.z;
    half _813 = _681.x;
    half3 _881 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _803)) + (half4(frame.sh[2]).xyz * _808)) + (half4(frame.sh[3]).xyz * _813)) + (((((half4(frame.sh[4]).xyz * (_813 * _803)) + (half4(frame.sh[5]).xyz * (_803 * _808))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _808, _808, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_813 * _808))) + (half4(frame.sh[8]).xyz * fma(_813, _813, half(-float(_803 * _803))))), half3(float3(0.0)));
    half _931 = max(dot(_681, half3(_685)), half(9.9999997473787516355514526367188e-05));
    float4 _970 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_931, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _989 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_970).y) - half(1.0)));
    float4 _996 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_685), _681)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1112 = fast::normalize(_685 + frame.lightDirection.xyz);
    half _1056 = clamp(dot(_681, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1173 = cross(_681, half3(_1112)) * half(64.0);
    half _1177 = clamp(dot(_681, half3(_1112)), half(0.0), half(1.0)) * (half(64.0) * half(params.facet_alpha));
    half _1159 = (half(4096.0) * half(params.facet_alpha)) / fma(_1177, _1177, dot(_1173, _1173));
    half _1192 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1198 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1226 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1112)), half(0.0), half(1.0));
    half _1229 = _1226 * _1226;
    half3 _1251 = fma(half3(float3(params.facet_diffuseColor)), _881, half4(_996).xyz * (mix(half4(_970).xxx, half4(_970).yyy, half3(float3(params.facet_f0))) * _989)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1229 * _1229) * _1226))) * min(min((_1159 * _1159) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1056, sqrt(fma(_931 * _931, _1198, _1192)), _931 * sqrt(fma(_1056 * _1056, _1198, _1192))), half(65504.0)), half(65504.0)), _989, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1056), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1251, half(1.0)));
    return out;
}

