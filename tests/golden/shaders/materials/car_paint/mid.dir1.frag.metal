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
    half3 _751 = normalize(half3(in.v_normal));
    half3 _841 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _965 = max(dot(_751, _841), half(9.9999997473787516355514526367188e-05));
    half3 _969 = reflect(-_841, _751);
    float4 _1004 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_965, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1023 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1004).y) - half(1.0)));
    float4 _1033 = facet_environment.sample(facet_environmentSmplr, float3(_969), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1080 = half(1.0) - _965;
    half _1083 = _1080 * _1080;
    half _1090 = fma(half(0.959999978542327880859375), (_1083 * _1083) * _1080, half(0.039999999105930328369140625));
    float4 _1068 = facet_environment.sample(facet_environmentSmplr, float3(_969), level(params.facet_clearCoatLod));
    half3 _798 = half4(frame.lightDirection).xyz;
    half3 _1217 = normalize(_841 + _798);
    half _1150 = clamp(dot(_751, _798), half(0.0), half(1.0));
    half _1154 = clamp(dot(_751, _1217), half(0.0), half(1.0));
    half _1158 = clamp(dot(_798, _1217), half(0.0), half(1.0));
    half3 _1280 = cross(_751, _1217) * half(64.0);
    half _1284 = (half(64.0) * half(params.facet_alpha)) * _1154;
    half _1287 = dot(_1280, _1280);
    half _1263 = half(6.283185482025146484375) * max(mix((half(2.0) * _1150) * _965, _1150 + _965, half(params.facet_alpha)), half(0.000244140625));
    half _1265 = (half(4096.0) * half(params.facet_alpha)) / (fma(_1284, _1284, _1287) * _1263);
    half _1374 = (half(64.0) * half(params.facet_clearCoatAlpha)) * _1154;
    half _1326 = half(12.56637096405029296875) * max(_1158 * _1158, half(6.103515625e-05));
    half _1332 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1374, _1374, _1287) * _1326);
    half _1342 = half(1.0) - _1158;
    half _1345 = _1342 * _1342;
    half3 _1404 = mix(half4(_1033).xyz * (mix(half4(_1004).xxx, half4(_1004).yyy, half3(float3(params.facet_f0))) * _1023), half4(_1068).xyz, half3(_1090 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1265 * (_1265 * _1263), half(65504.0))) * _1023) * fma(half(-float(_1090)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1332 * (_1332 * _1326), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * ((_1345 * _1345) * _1342))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1150), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1404, half(1.0)));
    return out;
}

