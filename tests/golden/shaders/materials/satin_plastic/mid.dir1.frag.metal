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
    half3 _701 = normalize(half3(in.v_normal));
    float3 _705 = fast::normalize(in.v_toEye);
    half _859 = max(dot(_701, half3(_705)), half(9.9999997473787516355514526367188e-05));
    half3 _863 = reflect(-half3(_705), _701);
    float4 _898 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_859, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _917 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_898).y) - half(1.0)));
    float4 _924 = facet_environment.sample(facet_environmentSmplr, float3(_863), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _997 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _957 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_859, _997)), level(0.0));
    half3 _1004 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1439 = half4(_957);
    half _970 = _1439.z;
    half _972 = fma(half(-float(max(_1004.x, max(_1004.y, _1004.z)))), _970, half(1.0));
    float4 _1011 = facet_environment.sample(facet_environmentSmplr, float3(_863), level(_997 * half(4.0)));
    half3 _761 = half4(frame.lightDirection).xyz;
    half3 _773 = half4(frame.lightColor).xyz;
    half3 _1142 = normalize(half3(_705) + _761);
    half _1090 = clamp(dot(_701, _761), half(0.0), half(1.0));
    half _1094 = clamp(dot(_701, _1142), half(0.0), half(1.0));
    half3 _1169 = cross(_701, _1142);
    half _1172 = _1094 * half(params.facet_alpha);
    half _1186 = _1090 + _859;
    half _1189 = max(mix((half(2.0) * _1090) * _859, _1186, half(params.facet_alpha)), half(0.000244140625));
    half _1196 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1172, _1172, dot(_1169, _1169)) * (half(6433.98193359375) * _1189));
    half _1264 = _997 * _997;
    half _1284 = half(8192.0) * fma(half(-float(_1090)), _859, _1186);
    half _1288 = half(1.0) / (_1264 * _1284);
    half3 _1329 = fma(half4(_1011).xyz, _1004 * _970, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_924).xyz * (mix(half4(_898).xxx, half4(_898).yyy, half3(float3(params.facet_f0))) * _917)) * _972) + (min(((half3(float3(params.facet_f0)) * min(_1196 * (_1196 * (half(6.283185482025146484375) * _1189)), half(65504.0))) * _917) * ((_773 * _1090) * _972), half3(float3(65504.0))) + min((_1004 * ((((fma(_1288, _1284, half(2.0)) * pow(max(fma(half(-float(_1094)), _1094, half(1.0)), half(0.0)), half(0.5) * (_1288 * _1284))) * half(0.15915493667125701904296875)) * (_1090 * (_1288 * (half(2048.0) * _1264)))) * half4(_957).w)) * _773, half3(float3(65504.0))));
    out.fragColor = float4(half4(_1329, half(1.0)));
    return out;
}

