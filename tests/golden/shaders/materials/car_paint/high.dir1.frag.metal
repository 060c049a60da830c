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
    half3 _862 = normalize(half3(in.v_normal));
    float3 _866 = fast::normalize(in.v_toEye);
    half _1133 = max(dot(_862, half3(_866)), half(9.9999997473787516355514526367188e-05));
    half3 _1137 = reflect(-half3(_866), _862);
    float4 _1172 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1133, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1191 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1172).y) - half(1.0)));
    float4 _1203 = facet_environment.sample(facet_environmentSmplr, float3(_1137), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1251 = half(1.0) - _1133;
    half _1254 = _1251 * _1251;
    half _1261 = fma(half(0.959999978542327880859375), (_1254 * _1254) * _1251, half(0.039999999105930328369140625));
    half _1266 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1271 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1283 = facet_environment.sample(facet_environmentSmplr, float3(_1137), level(_1271 * (half(4.0) * (half(2.0) - _1271))));
    float3 _1408 = fast::normalize(_866 + frame.lightDirection.xyz);
    half _1341 = clamp(dot(_862, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1345 = clamp(dot(_862, half3(_1408)), half(0.0), half(1.0));
    half _1349 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1408)), half(0.0), half(1.0));
    half3 _1448 = cross(_862, half3(_1408));
    half _1451 = _1345 * half(params.facet_alpha);
    half _1455 = dot(_1448, _1448);
    half _1460 = half(params.facet_alpha) / fma(_1451, _1451, _1455);
    half _1474 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1480 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1508 = half(1.0) - _1349;
    half _1511 = _1508 * _1508;
    half _1516 = (_1511 * _1511) * _1508;
    half3 _1367 = half4(frame.lightColor).xyz * _1341;
    half _1553 = _1271 * _1271;
    half _1559 = _1345 * _1553;
    half _1570 = max(_1349 * _1349, half(6.103515625e-05));
    half _1578 = (half(2048.0) * _1553) / (fma(_1559, _1559, _1455) * (_1570 * half(25735.927734375)));
    half3 _1641 = mix(half4(_1203).xyz * (mix(half4(_1172).xxx, half4(_1172).yyy, half3(float3(params.facet_f0))) * _1191), half4(_1283).xyz, half3(_1261 * _1266)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1516)) * min(min((_1460 * _1460) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1341, sqrt(fma(_1133 * _1133, _1480, _1474)), _1133 * sqrt(fma(_1341 * _1341, _1480, _1474))), half(65504.0)), half(65504.0))) * _1191, _1367 * fma(half(-float(_1261)), _1266, half(1.0)), _1367 * (min(_1578 * (_1578 * (half(12.56637096405029296875) * _1570)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1516, half(0.039999999105930328369140625)) * _1266))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1641, half(1.0)));
    return out;
}

