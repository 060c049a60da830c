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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _742 = normalize(half3(in.v_normal));
    half3 _834 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _958 = max(dot(_742, _834), half(9.9999997473787516355514526367188e-05));
    half3 _962 = reflect(-_834, _742);
    float4 _998 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_958, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1027 = facet_environment.sample(facet_environmentSmplr, float3(_962), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _977 = mix(half4(_998).xxx, half4(_998).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_998).y) - half(1.0))));
    half _1074 = half(1.0) - _958;
    half _1077 = _1074 * _1074;
    half _1084 = fma(half(0.959999978542327880859375), (_1077 * _1077) * _1074, half(0.039999999105930328369140625));
    float4 _1062 = facet_environment.sample(facet_environmentSmplr, float3(_962), level(params.facet_clearCoatLod));
    half3 _789 = half4(frame.lightDirection).xyz;
    half3 _1208 = normalize(_834 + _789);
    half _1152 = clamp(dot(_789, _1208), half(0.0), half(1.0));
    half _1233 = clamp(dot(_962, _789), half(0.0), half(1.0));
    half _1236 = _1233 * _1233;
    half4 _1495 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1236 * _1236, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1248 = _1495.x;
    half3 _1331 = cross(_742, _1208) * half(64.0);
    half _1335 = (half(64.0) * half(params.facet_clearCoatAlpha)) * clamp(dot(_742, _1208), half(0.0), half(1.0));
    half _1287 = half(12.56637096405029296875) * max(_1152 * _1152, half(6.103515625e-05));
    half _1293 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1335, _1335, dot(_1331, _1331)) * _1287);
    half _1303 = half(1.0) - _1152;
    half _1306 = _1303 * _1303;
    half3 _1365 = mix(half4(_1027).xyz * _977, half4(_1062).xyz, half3(_1084 * half(params.facet_clearCoat))) + min(min(((_977 * ((_1248 * _1248) * half(5.092957973480224609375))) * fma(half(-float(_1084)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1293 * (_1293 * _1287), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * ((_1306 * _1306) * _1303))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_742, _789), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1365, half(1.0)));
    return out;
}

