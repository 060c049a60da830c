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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _652 = normalize(half3(in.v_normal));
    float3 _668 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _858 = max(dot(_652, half3(_668)), half(9.9999997473787516355514526367188e-05));
    half3 _862 = reflect(-half3(_668), _652);
    float4 _897 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_858, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _916 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_897).y) - half(1.0)));
    float4 _926 = facet_environment.sample(facet_environmentSmplr, float3(_862), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _706 = half4(frame.lightDirection).xyz;
    half3 _1033 = normalize(half3(_668) + _706);
    half _984 = clamp(dot(_652, _706), half(0.0), half(1.0));
    half3 _1060 = cross(_652, _1033);
    half _1063 = clamp(dot(_652, _1033), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1080 = max(mix((half(2.0) * _984) * _858, _984 + _858, half(params.facet_alpha)), half(0.000244140625));
    half _1082 = half(1024.0) * half(params.facet_alpha);
    half _1087 = _1082 / (fma(_1063, _1063, dot(_1060, _1060)) * (half(6433.98193359375) * _1080));
    float3 _1135 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1138 = dot(_1135, _1135);
    float3 _1143 = _1135 * rsqrt(fast::max(_1138, 9.9999999392252902907785028219223e-09));
    float _1147 = _1138 * float(frame.punctualLights[0].positionFalloff.w);
    float _1152 = fast::clamp(fma(-_1147, _1147, 1.0), 0.0, 1.0);
    float _1171 = fast::clamp(fma(dot(-_1143, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1281 = normalize(half3(_668) + half3(_1143));
    half _1232 = clamp(dot(_652, half3(_1143)), half(0.0), half(1.0));
    half3 _1308 = cross(_652, _1281);
    half _1311 = clamp(dot(_652, _1281), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1328 = max(mix((half(2.0) * _1232) * _858, _1232 + _858, half(params.facet_alpha)), half(0.000244140625));
    half _1335 = _1082 / (fma(_1311, _1311, dot(_1308, _1308)) * (half(6433.98193359375) * _1328));
    float3 _1383 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1386 = dot(_1383, _1383);
    float3 _1391 = _1383 * rsqrt(fast::max(_1386, 9.9999999392252902907785028219223e-09));
    float _1395 = _1386 * float(frame.punctualLights[1].positionFalloff.w);
    float _1400 = fast::clamp(fma(-_1395, _1395, 1.0), 0.0, 1.0);
    float _1419 = fast::clamp(fma(dot(-_1391, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1529 = normalize(half3(_668) + half3(_1391));
    half _1480 = clamp(dot(_652, half3(_1391)), half(0.0), half(1.0));
    half3 _1556 = cross(_652, _1529);
    half _1559 = clamp(dot(_652, _1529), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1576 = max(mix((half(2.0) * _1480) * _858, _1480 + _858, half(params.facet_alpha)), half(0.000244140625));
    half _1583 = _1082 / (fma(_1559, _1559, dot(_1556, _1556)) * (half(6433.98193359375) * _1576));
    half3 _1595 = (fma(half4(_926).xyz, mix(half4(_897).xxx, half4(_897).yyy, half3(float3(params.facet_f0))) * _916, min(((half3(float3(params.facet_f0)) * min(_1087 * (_1087 * (half(6.283185482025146484375) * _1080)), half(65504.0))) * _916) * (half4(frame.lightColor).xyz * _984), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1335 * (_1335 * (half(6.283185482025146484375) * _1328)), half(65504.0))) * _916) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1152) * half(_1152)) / fast::max(_1138, 9.9999997473787516355514526367188e-05)) * half(_1171)) * half(_1171)), float3(65504.0))) * _1232), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1583 * (_1583 * (half(6.283185482025146484375) * _1576)), half(65504.0))) * _916) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1400) * half(_1400)) / fast::max(_1386, 9.9999997473787516355514526367188e-05)) * half(_1419)) * half(_1419)), float3(65504.0))) * _1480), half3(float3(65504.0)));
    half _1634 = half(1.0) - _858;
    half _1637 = _1634 * _1634;
    half _1654 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1664 = facet_environment.sample(facet_environmentSmplr, float3(_862), level(_1654 * (half(4.0) * (half(2.0) - _1654))));
    out.fragColor = float4(half4(mix(_1595, half4(_1664).xyz, half3(fma(half(0.959999978542327880859375), (_1637 * _1637) * _1634, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

