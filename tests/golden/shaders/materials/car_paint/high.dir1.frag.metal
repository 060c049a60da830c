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
    half3 _860 = normalize(half3(in.v_normal));
    float3 _864 = fast::normalize(in.v_toEye);
    half _1131 = max(dot(_860, half3(_864)), half(9.9999997473787516355514526367188e-05));
    half3 _1135 = reflect(-half3(_864), _860);
    float4 _1170 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1131, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1189 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1170).y) - half(1.0)));
    float4 _1199 = facet_environment.sample(facet_environmentSmplr, float3(_1135), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1247 = half(1.0) - _1131;
    half _1250 = _1247 * _1247;
    half _1257 = fma(half(0.959999978542327880859375), (_1250 * _1250) * _1247, half(0.039999999105930328369140625));
    half _1262 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1267 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1277 = facet_environment.sample(facet_environmentSmplr, float3(_1135), level(_1267 * (half(4.0) * (half(2.0) - _1267))));
    float3 _1402 = fast::normalize(_864 + frame.lightDirection.xyz);
    half _1335 = clamp(dot(_860, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1339 = clamp(dot(_860, half3(_1402)), half(0.0), half(1.0));
    half _1343 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1402)), half(0.0), half(1.0));
    half3 _1442 = cross(_860, half3(_1402));
    half _1445 = _1339 * half(params.facet_alpha);
    half _1449 = dot(_1442, _1442);
    half _1454 = half(params.facet_alpha) / fma(_1445, _1445, _1449);
    half _1468 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1474 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1502 = half(1.0) - _1343;
    half _1505 = _1502 * _1502;
    half _1510 = (_1505 * _1505) * _1502;
    half3 _1361 = half4(frame.lightColor).xyz * _1335;
    half _1547 = _1267 * _1267;
    half _1553 = _1339 * _1547;
    half _1564 = max(_1343 * _1343, half(6.103515625e-05));
    half _1572 = (half(2048.0) * _1547) / (fma(_1553, _1553, _1449) * (_1564 * half(25735.927734375)));
    half3 _1635 = mix(half4(_1199).xyz * (mix(half4(_1170).xxx, half4(_1170).yyy, half3(float3(params.facet_f0))) * _1189), half4(_1277).xyz, half3(_1257 * _1262)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1510)) * min(min((_1454 * _1454) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1335, sqrt(fma(_1131 * _1131, _1474, _1468)), _1131 * sqrt(fma(_1335 * _1335, _1474, _1468))), half(65504.0)), half(65504.0))) * _1189, _1361 * fma(half(-float(_1257)), _1262, half(1.0)), _1361 * (min(_1572 * (_1572 * (half(12.56637096405029296875) * _1564)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1510, half(0.039999999105930328369140625)) * _1262))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1635, half(1.0)));
    return out;
}

