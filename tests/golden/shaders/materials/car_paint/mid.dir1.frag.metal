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
    half3 _739 = normalize(half3(in.v_normal));
    float3 _743 = fast::normalize(in.v_toEye);
    half _942 = max(dot(_739, half3(_743)), half(9.9999997473787516355514526367188e-05));
    half3 _946 = reflect(-half3(_743), _739);
    float4 _981 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_942, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1000 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_981).y) - half(1.0)));
    float4 _1010 = facet_environment.sample(facet_environmentSmplr, float3(_946), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1057 = half(1.0) - _942;
    half _1060 = _1057 * _1057;
    half _1067 = fma(half(0.959999978542327880859375), (_1060 * _1060) * _1057, half(0.039999999105930328369140625));
    float4 _1045 = facet_environment.sample(facet_environmentSmplr, float3(_946), level(params.facet_clearCoatLod));
    half3 _785 = half4(frame.lightDirection).xyz;
    half3 _1194 = normalize(half3(_743) + _785);
    half _1127 = clamp(dot(_739, _785), half(0.0), half(1.0));
    half _1131 = clamp(dot(_739, _1194), half(0.0), half(1.0));
    half _1135 = clamp(dot(_785, _1194), half(0.0), half(1.0));
    half3 _1257 = cross(_739, _1194) * half(64.0);
    half _1261 = (half(64.0) * half(params.facet_alpha)) * _1131;
    half _1264 = dot(_1257, _1257);
    half _1240 = half(6.283185482025146484375) * max(mix((half(2.0) * _1127) * _942, _1127 + _942, half(params.facet_alpha)), half(0.000244140625));
    half _1242 = (half(4096.0) * half(params.facet_alpha)) / (fma(_1261, _1261, _1264) * _1240);
    half _1351 = (half(64.0) * half(params.facet_clearCoatAlpha)) * _1131;
    half _1303 = half(12.56637096405029296875) * max(_1135 * _1135, half(6.103515625e-05));
    half _1309 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1351, _1351, _1264) * _1303);
    half _1319 = half(1.0) - _1135;
    half _1322 = _1319 * _1319;
    half3 _1381 = mix(half4(_1010).xyz * (mix(half4(_981).xxx, half4(_981).yyy, half3(float3(params.facet_f0))) * _1000), half4(_1045).xyz, half3(_1067 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1242 * (_1242 * _1240), half(65504.0))) * _1000) * fma(half(-float(_1067)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1309 * (_1309 * _1303), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * ((_1322 * _1322) * _1319))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1127), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1381, half(1.0)));
    return out;
}

