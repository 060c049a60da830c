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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _660 = normalize(half3(in.v_normal));
    float3 _676 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _867 = max(dot(_660, half3(_676)), half(9.9999997473787516355514526367188e-05));
    half3 _871 = reflect(-half3(_676), _660);
    float4 _906 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_867, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _925 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_906).y) - half(1.0)));
    float4 _935 = facet_environment.sample(facet_environmentSmplr, float3(_871), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _714 = half4(frame.lightDirection).xyz;
    half3 _1042 = normalize(half3(_676) + _714);
    half _993 = clamp(dot(_660, _714), half(0.0), half(1.0));
    half4 _1111 = half4(cross(_660, _1042), half(params.facet_alpha) * clamp(dot(_660, _1042), half(0.0), half(1.0))) * half(64.0);
    half _1085 = half(4096.0) * half(params.facet_alpha);
    half _1088 = half(6.283185482025146484375) * max(mix((half(2.0) * _993) * _867, _993 + _867, half(params.facet_alpha)), half(0.000244140625));
    half _1090 = _1085 / (dot(_1111, _1111) * _1088);
    float3 _1155 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1158 = dot(_1155, _1155);
    float3 _1163 = _1155 * rsqrt(fast::max(_1158, 9.9999999392252902907785028219223e-09));
    float _1167 = _1158 * float(frame.punctualLights[0].positionFalloff.w);
    float _1172 = fast::clamp(fma(-_1167, _1167, 1.0), 0.0, 1.0);
    float _1191 = fast::clamp(fma(dot(-_1163, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1301 = normalize(half3(_676) + half3(_1163));
    half _1252 = clamp(dot(_660, half3(_1163)), half(0.0), half(1.0));
    half4 _1370 = half4(cross(_660, _1301), half(params.facet_alpha) * clamp(dot(_660, _1301), half(0.0), half(1.0))) * half(64.0);
    half _1347 = half(6.283185482025146484375) * max(mix((half(2.0) * _1252) * _867, _1252 + _867, half(params.facet_alpha)), half(0.000244140625));
    half _1349 = _1085 / (dot(_1370, _1370) * _1347);
    float3 _1414 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1417 = dot(_1414, _1414);
    float3 _1422 = _1414 * rsqrt(fast::max(_1417, 9.9999999392252902907785028219223e-09));
    float _1426 = _1417 * float(frame.punctualLights[1].positionFalloff.w);
    float _1431 = fast::clamp(fma(-_1426, _1426, 1.0), 0.0, 1.0);
    float _1450 = fast::clamp(fma(dot(-_1422, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1560 = normalize(half3(_676) + half3(_1422));
    half _1511 = clamp(dot(_660, half3(_1422)), half(0.0), half(1.0));
    half4 _1629 = half4(cross(_660, _1560), half(params.facet_alpha) * clamp(dot(_660, _1560), half(0.0), half(1.0))) * half(64.0);
    half _1606 = half(6.283185482025146484375) * max(mix((half(2.0) * _1511) * _867, _1511 + _867, half(params.facet_alpha)), half(0.000244140625));
    half _1608 = _1085 / (dot(_1629, _1629) * _1606);
    half3 _1637 = (fma(half4(_935).xyz, mix(half4(_906).xxx, half4(_906).yyy, half3(float3(params.facet_f0))) * _925, min(((half3(float3(params.facet_f0)) * min(_1090 * (_1090 * _1088), half(65504.0))) * _925) * (half4(frame.lightColor).xyz * _993), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1349 * (_1349 * _1347), half(65504.0))) * _925) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1172) * half(_1172)) / fast::max(_1158, 9.9999997473787516355514526367188e-05)) * half(_1191)) * half(_1191)), float3(65504.0))) * _1252), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1608 * (_1608 * _1606), half(65504.0))) * _925) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1431) * half(_1431)) / fast::max(_1417, 9.9999997473787516355514526367188e-05)) * half(_1450)) * half(_1450)), float3(65504.0))) * _1511), half3(float3(65504.0)));
    half _1675 = half(1.0) - _867;
    half _1678 = _1675 * _1675;
    float4 _1663 = facet_environment.sample(facet_environmentSmplr, float3(_871), level(params.facet_clearCoatLod));
    half3 _1669 = mix(_1637, half4(_1663).xyz, half3(fma(half(0.959999978542327880859375), (_1678 * _1678) * _1675, half(0.039999999105930328369140625)) * half(params.facet_clearCoat)));
    out.fragColor = float4(half4(_1669, half(1.0)));
    return out;
}

