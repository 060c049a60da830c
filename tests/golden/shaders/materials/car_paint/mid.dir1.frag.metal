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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _737 = normalize(half3(in.v_normal));
    half3 _827 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _949 = max(dot(_737, _827), half(9.9999997473787516355514526367188e-05));
    half3 _953 = reflect(-_827, _737);
    float4 _991 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_949, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1010 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_991).y) - half(1.0)));
    float4 _967 = facet_environment.sample(facet_environmentSmplr, float3(_953), level(params.facet_environmentLod));
    half _1056 = half(1.0) - _949;
    half _1059 = _1056 * _1056;
    half _1066 = fma(half(0.959999978542327880859375), (_1059 * _1059) * _1056, half(0.039999999105930328369140625));
    float4 _1044 = facet_environment.sample(facet_environmentSmplr, float3(_953), level(params.facet_clearCoatLod));
    half3 _784 = half4(frame.lightDirection).xyz;
    half _1123 = clamp(dot(_737, _784), half(0.0), half(1.0));
    half3 _1193 = normalize(_827 + _784);
    half _1130 = clamp(dot(_737, _1193), half(0.0), half(1.0));
    half _1134 = clamp(dot(_784, _1193), half(0.0), half(1.0));
    half3 _1256 = cross(_737, _1193) * half(64.0);
    half _1260 = (half(64.0) * half(params.facet_alpha)) * _1130;
    half _1263 = dot(_1256, _1256);
    half _1239 = half(6.283185482025146484375) * max(mix((half(2.0) * _1123) * _949, _1123 + _949, half(params.facet_alpha)), half(0.000244140625));
    half _1241 = (half(4096.0) * half(params.facet_alpha)) / (fma(_1260, _1260, _1263) * _1239);
    half _1350 = (half(64.0) * half(params.facet_clearCoatAlpha)) * _1130;
    half _1302 = half(12.56637096405029296875) * max(_1134 * _1134, half(6.103515625e-05));
    half _1308 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1350, _1350, _1263) * _1302);
    half _1318 = half(1.0) - _1134;
    half _1321 = _1318 * _1318;
    half3 _1380 = mix(half4(_967).xyz * (mix(half4(_991).xxx, half4(_991).yyy, half3(float3(params.facet_f0))) * _1010), half4(_1044).xyz, half3(_1066 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1241 * (_1241 * _1239), half(65504.0))) * _1010) * fma(half(-float(_1066)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1308 * (_1308 * _1302), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * ((_1321 * _1321) * _1318))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1123), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1380, half(1.0)));
    return out;
}

