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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _637 = normalize(half3(in.v_normal));
    float3 _641 = fast::normalize(in.v_toEye);
    half _798 = max(dot(_637, half3(_641)), half(9.9999997473787516355514526367188e-05));
    half3 _802 = reflect(-half3(_641), _637);
    float4 _838 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_798, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _864 = facet_environment.sample(facet_environmentSmplr, float3(_802), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _817 = mix(half4(_838).xxx, half4(_838).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_838).y) - half(1.0))));
    half _941 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _898 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_798, _941)), level(0.0));
    half3 _948 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1297 = half4(_898);
    half _911 = _1297.z;
    half _913 = fma(half(-float(max(_948.x, max(_948.y, _948.z)))), _911, half(1.0));
    half _957 = _941 * _941;
    float4 _969 = facet_environment.sample(facet_environmentSmplr, float3(_802), level(_941 * half(4.0)));
    half3 _697 = half4(frame.lightDirection).xyz;
    half3 _709 = half4(frame.lightColor).xyz;
    half _1024 = clamp(dot(_637, _697), half(0.0), half(1.0));
    half _1028 = clamp(dot(_637, normalize(half3(_641) + _697)), half(0.0), half(1.0));
    half _1107 = clamp(dot(_802, _697), half(0.0), half(1.0));
    half _1110 = _1107 * _1107;
    half4 _1319 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1110 * _1110, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1122 = _1319.x;
    half _1156 = half(8192.0) * fma(half(-float(_1024)), _798, _1024 + _798);
    half _1160 = half(1.0) / (_957 * _1156);
    half3 _1189 = fma(half4(_969).xyz, _948 * _911, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_864).xyz * _817) * _913) + min(fma(_817 * ((_1122 * _1122) * half(5.092957973480224609375)), (_709 * _1024) * _913, (_948 * ((((fma(_1160, _1156, half(2.0)) * pow(max(fma(half(-float(_1028)), _1028, half(1.0)), half(0.0)), half(0.5) * (_1160 * _1156))) * half(0.15915493667125701904296875)) * (_1024 * (_1160 * (half(2048.0) * _957)))) * half4(_898).w)) * _709), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1189, half(1.0)));
    return out;
}

