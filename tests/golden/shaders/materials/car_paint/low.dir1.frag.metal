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
    half3 _730 = normalize(half3(in.v_normal));
    float3 _734 = fast::normalize(in.v_toEye);
    half _935 = max(dot(_730, half3(_734)), half(9.9999997473787516355514526367188e-05));
    half3 _939 = reflect(-half3(_734), _730);
    float4 _975 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_935, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1004 = facet_environment.sample(facet_environmentSmplr, float3(_939), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _954 = mix(half4(_975).xxx, half4(_975).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_975).y) - half(1.0))));
    half _1051 = half(1.0) - _935;
    half _1054 = _1051 * _1051;
    half _1061 = fma(half(0.959999978542327880859375), (_1054 * _1054) * _1051, half(0.039999999105930328369140625));
    float4 _1039 = facet_environment.sample(facet_environmentSmplr, float3(_939), level(params.facet_clearCoatLod));
    half3 _776 = half4(frame.lightDirection).xyz;
    half3 _1185 = normalize(half3(_734) + _776);
    half _1129 = clamp(dot(_776, _1185), half(0.0), half(1.0));
    half _1210 = clamp(dot(_939, _776), half(0.0), half(1.0));
    half _1213 = _1210 * _1210;
    half4 _1471 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1213 * _1213, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1225 = _1471.x;
    half3 _1308 = cross(_730, _1185) * half(64.0);
    half _1312 = (half(64.0) * half(params.facet_clearCoatAlpha)) * clamp(dot(_730, _1185), half(0.0), half(1.0));
    half _1264 = half(12.56637096405029296875) * max(_1129 * _1129, half(6.103515625e-05));
    half _1270 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1312, _1312, dot(_1308, _1308)) * _1264);
    half _1280 = half(1.0) - _1129;
    half _1283 = _1280 * _1280;
    half3 _1342 = mix(half4(_1004).xyz * _954, half4(_1039).xyz, half3(_1061 * half(params.facet_clearCoat))) + min(min(((_954 * ((_1225 * _1225) * half(5.092957973480224609375))) * fma(half(-float(_1061)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1270 * (_1270 * _1264), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * ((_1283 * _1283) * _1280))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_730, _776), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1342, half(1.0)));
    return out;
}

