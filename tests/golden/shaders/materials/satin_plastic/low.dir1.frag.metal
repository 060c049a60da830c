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
    half3 _684 = normalize(half3(in.v_normal));
    float3 _688 = fast::normalize(in.v_toEye);
    half _845 = max(dot(_684, half3(_688)), half(9.9999997473787516355514526367188e-05));
    half3 _849 = reflect(-half3(_688), _684);
    float4 _885 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _911 = facet_environment.sample(facet_environmentSmplr, float3(_849), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _864 = mix(half4(_885).xxx, half4(_885).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_885).y) - half(1.0))));
    half _984 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _944 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, _984)), level(0.0));
    half3 _991 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1406 = half4(_944);
    half _957 = _1406.z;
    half _959 = fma(half(-float(max(_991.x, max(_991.y, _991.z)))), _957, half(1.0));
    float4 _998 = facet_environment.sample(facet_environmentSmplr, float3(_849), level(_984 * half(4.0)));
    half3 _744 = half4(frame.lightDirection).xyz;
    half3 _756 = half4(frame.lightColor).xyz;
    half _1077 = clamp(dot(_684, _744), half(0.0), half(1.0));
    half _1151 = clamp(dot(_849, _744), half(0.0), half(1.0));
    half _1154 = _1151 * _1151;
    half4 _1425 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1154 * _1154, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1166 = _1425.x;
    half _1204 = clamp(dot(_684, normalize(half3(_688) + _744)), half(0.0), half(1.0));
    half _1231 = _984 * _984;
    half _1251 = half(8192.0) * fma(half(-float(_1077)), _845, _1077 + _845);
    half _1255 = half(1.0) / (_1231 * _1251);
    half3 _1296 = fma(half4(_998).xyz, _991 * _957, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_911).xyz * _864) * _959) + (min((_864 * ((_1166 * _1166) * half(5.092957973480224609375))) * ((_756 * _1077) * _959), half3(float3(65504.0))) + min((_991 * ((((fma(_1255, _1251, half(2.0)) * pow(max(fma(half(-float(_1204)), _1204, half(1.0)), half(0.0)), half(0.5) * (_1255 * _1251))) * half(0.15915493667125701904296875)) * (_1077 * (_1255 * (half(2048.0) * _1231)))) * half4(_944).w)) * _756, half3(float3(65504.0))));
    out.fragColor = float4(half4(_1296, half(1.0)));
    return out;
}

