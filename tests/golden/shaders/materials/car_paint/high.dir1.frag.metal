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
    half3 _858 = normalize(half3(in.v_normal));
    float3 _862 = fast::normalize(in.v_toEye);
    half _1129 = max(dot(_858, half3(_862)), half(9.9999997473787516355514526367188e-05));
    half3 _1133 = reflect(-half3(_862), _858);
    float4 _1168 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1129, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1187 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1168).y) - half(1.0)));
    float4 _1194 = facet_environment.sample(facet_environmentSmplr, float3(_1133), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1242 = half(1.0) - _1129;
    half _1245 = _1242 * _1242;
    half _1252 = fma(half(0.959999978542327880859375), (_1245 * _1245) * _1242, half(0.039999999105930328369140625));
    half _1257 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1262 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1269 = facet_environment.sample(facet_environmentSmplr, float3(_1133), level(_1262 * half(4.0)));
    float3 _1394 = fast::normalize(_862 + frame.lightDirection.xyz);
    half _1327 = clamp(dot(_858, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1331 = clamp(dot(_858, half3(_1394)), half(0.0), half(1.0));
    half _1335 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1394)), half(0.0), half(1.0));
    half3 _1434 = cross(_858, half3(_1394));
    half _1437 = _1331 * half(params.facet_alpha);
    half _1446 = half(params.facet_alpha) / fma(_1437, _1437, dot(_1434, _1434));
    half _1460 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1466 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1494 = half(1.0) - _1335;
    half _1497 = _1494 * _1494;
    half _1502 = (_1497 * _1497) * _1494;
    half3 _1353 = half4(frame.lightColor).xyz * _1327;
    half _1539 = _1262 * _1262;
    half3 _1543 = _1434 * half(64.0);
    half _1547 = _1331 * (half(64.0) * _1539);
    half _1559 = half(12.56637096405029296875) * max(_1335 * _1335, half(6.103515625e-05));
    half _1565 = (half(4096.0) * _1539) / (fma(_1547, _1547, dot(_1543, _1543)) * _1559);
    half3 _1628 = mix(half4(_1194).xyz * (mix(half4(_1168).xxx, half4(_1168).yyy, half3(float3(params.facet_f0))) * _1187), half4(_1269).xyz, half3(_1252 * _1257)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1502)) * min(min((_1446 * _1446) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1327, sqrt(fma(_1129 * _1129, _1466, _1460)), _1129 * sqrt(fma(_1327 * _1327, _1466, _1460))), half(65504.0)), half(65504.0))) * _1187, _1353 * fma(half(-float(_1252)), _1257, half(1.0)), _1353 * (min(_1565 * (_1565 * _1559), half(65504.0)) * (fma(half(0.959999978542327880859375), _1502, half(0.039999999105930328369140625)) * _1257))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1628, half(1.0)));
    return out;
}

