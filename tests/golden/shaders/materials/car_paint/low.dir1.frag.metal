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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _727 = normalize(half3(in.v_normal));
    half3 _819 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _941 = max(dot(_727, _819), half(9.9999997473787516355514526367188e-05));
    half3 _945 = reflect(-_819, _727);
    float4 _984 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_941, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _959 = facet_environment.sample(facet_environmentSmplr, float3(_945), level(params.facet_environmentLod));
    half3 _963 = mix(half4(_984).xxx, half4(_984).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_984).y) - half(1.0))));
    half _1049 = half(1.0) - _941;
    half _1052 = _1049 * _1049;
    half _1059 = fma(half(0.959999978542327880859375), (_1052 * _1052) * _1049, half(0.039999999105930328369140625));
    float4 _1037 = facet_environment.sample(facet_environmentSmplr, float3(_945), level(params.facet_clearCoatLod));
    half3 _774 = half4(frame.lightDirection).xyz;
    half3 _1183 = normalize(_819 + _774);
    half _1127 = clamp(dot(_774, _1183), half(0.0), half(1.0));
    half _1208 = clamp(dot(_945, _774), half(0.0), half(1.0));
    half _1211 = _1208 * _1208;
    half4 _1466 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1211 * _1211, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1223 = _1466.x;
    half3 _1306 = cross(_727, _1183) * half(64.0);
    half _1310 = (half(64.0) * half(params.facet_clearCoatAlpha)) * clamp(dot(_727, _1183), half(0.0), half(1.0));
    half _1262 = half(12.56637096405029296875) * max(_1127 * _1127, half(6.103515625e-05));
    half _1268 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1310, _1310, dot(_1306, _1306)) * _1262);
    half _1278 = half(1.0) - _1127;
    half _1281 = _1278 * _1278;
    half3 _1340 = mix(half4(_959).xyz * _963, half4(_1037).xyz, half3(_1059 * half(params.facet_clearCoat))) + min(min(((_963 * ((_1223 * _1223) * half(5.092957973480224609375))) * fma(half(-float(_1059)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1268 * (_1268 * _1262), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * ((_1281 * _1281) * _1278))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_727, _774), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1340, half(1.0)));
    return out;
}

