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
    half3 _667 = normalize(half3(in.v_normal));
    float3 _683 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _873 = max(dot(_667, half3(_683)), half(9.9999997473787516355514526367188e-05));
    half3 _877 = reflect(-half3(_683), _667);
    float4 _912 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_873, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _931 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_912).y) - half(1.0)));
    float4 _938 = facet_environment.sample(facet_environmentSmplr, float3(_877), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _721 = half4(frame.lightDirection).xyz;
    half3 _1045 = normalize(half3(_683) + _721);
    half _996 = clamp(dot(_667, _721), half(0.0), half(1.0));
    half4 _1114 = half4(cross(_667, _1045), half(params.facet_alpha) * clamp(dot(_667, _1045), half(0.0), half(1.0))) * half(64.0);
    half _1088 = half(4096.0) * half(params.facet_alpha);
    half _1091 = half(6.283185482025146484375) * max(mix((half(2.0) * _996) * _873, _996 + _873, half(params.facet_alpha)), half(0.000244140625));
    half _1093 = _1088 / (dot(_1114, _1114) * _1091);
    float3 _1158 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1161 = dot(_1158, _1158);
    float3 _1166 = _1158 * rsqrt(fast::max(_1161, 9.9999999392252902907785028219223e-09));
    float _1170 = _1161 * float(frame.punctualLights[0].positionFalloff.w);
    float _1175 = fast::clamp(fma(-_1170, _1170, 1.0), 0.0, 1.0);
    float _1194 = fast::clamp(fma(dot(-_1166, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1304 = normalize(half3(_683) + half3(_1166));
    half _1255 = clamp(dot(_667, half3(_1166)), half(0.0), half(1.0));
    half4 _1373 = half4(cross(_667, _1304), half(params.facet_alpha) * clamp(dot(_667, _1304), half(0.0), half(1.0))) * half(64.0);
    half _1350 = half(6.283185482025146484375) * max(mix((half(2.0) * _1255) * _873, _1255 + _873, half(params.facet_alpha)), half(0.000244140625));
    half _1352 = _1088 / (dot(_1373, _1373) * _1350);
    float3 _1417 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1420 = dot(_1417, _1417);
    float3 _1425 = _1417 * rsqrt(fast::max(_1420, 9.9999999392252902907785028219223e-09));
    float _1429 = _1420 * float(frame.punctualLights[1].positionFalloff.w);
    float _1434 = fast::clamp(fma(-_1429, _1429, 1.0), 0.0, 1.0);
    float _1453 = fast::clamp(fma(dot(-_1425, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1563 = normalize(half3(_683) + half3(_1425));
    half _1514 = clamp(dot(_667, half3(_1425)), half(0.0), half(1.0));
    half4 _1632 = half4(cross(_667, _1563), half(params.facet_alpha) * clamp(dot(_667, _1563), half(0.0), half(1.0))) * half(64.0);
    half _1609 = half(6.283185482025146484375) * max(mix((half(2.0) * _1514) * _873, _1514 + _873, half(params.facet_alpha)), half(0.000244140625));
    half _1611 = _1088 / (dot(_1632, _1632) * _1609);
    half3 _1640 = (fma(half4(_938).xyz, mix(half4(_912).xxx, half4(_912).yyy, half3(float3(params.facet_f0))) * _931, min(((half3(float3(params.facet_f0)) * min(_1093 * (_1093 * _1091), half(65504.0))) * _931) * (half4(frame.lightColor).xyz * _996), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1352 * (_1352 * _1350), half(65504.0))) * _931) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1175) * half(_1175)) / fast::max(_1161, 9.9999997473787516355514526367188e-05)) * half(_1194)) * half(_1194)), float3(65504.0))) * _1255), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1611 * (_1611 * _1609), half(65504.0))) * _931) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1434) * half(_1434)) / fast::max(_1420, 9.9999997473787516355514526367188e-05)) * half(_1453)) * half(_1453)), float3(65504.0))) * _1514), half3(float3(65504.0)));
    half _1679 = half(1.0) - _873;
    half _1682 = _1679 * _1679;
    float4 _1706 = facet_environment.sample(facet_environmentSmplr, float3(_877), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1673 = mix(_1640, half4(_1706).xyz, half3(fma(half(0.959999978542327880859375), (_1682 * _1682) * _1679, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1673, half(1.0)));
    return out;
}

