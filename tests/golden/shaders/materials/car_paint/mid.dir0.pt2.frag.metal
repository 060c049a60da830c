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
    half _837 = max(dot(_652, half3(_668)), half(9.9999997473787516355514526367188e-05));
    half3 _841 = reflect(-half3(_668), _652);
    float4 _876 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_837, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _895 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_876).y) - half(1.0)));
    float4 _905 = facet_environment.sample(facet_environmentSmplr, float3(_841), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _950 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _953 = dot(_950, _950);
    float3 _958 = _950 * rsqrt(fast::max(_953, 9.9999999392252902907785028219223e-09));
    float _962 = _953 * float(frame.punctualLights[0].positionFalloff.w);
    float _967 = fast::clamp(fma(-_962, _962, 1.0), 0.0, 1.0);
    float _986 = fast::clamp(fma(dot(-_958, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1096 = normalize(half3(_668) + half3(_958));
    half _1047 = clamp(dot(_652, half3(_958)), half(0.0), half(1.0));
    half3 _1123 = cross(_652, _1096);
    half _1126 = clamp(dot(_652, _1096), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1143 = max(mix((half(2.0) * _1047) * _837, _1047 + _837, half(params.facet_alpha)), half(0.000244140625));
    half _1145 = half(1024.0) * half(params.facet_alpha);
    half _1150 = _1145 / (fma(_1126, _1126, dot(_1123, _1123)) * (half(6433.98193359375) * _1143));
    float3 _1198 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1201 = dot(_1198, _1198);
    float3 _1206 = _1198 * rsqrt(fast::max(_1201, 9.9999999392252902907785028219223e-09));
    float _1210 = _1201 * float(frame.punctualLights[1].positionFalloff.w);
    float _1215 = fast::clamp(fma(-_1210, _1210, 1.0), 0.0, 1.0);
    float _1234 = fast::clamp(fma(dot(-_1206, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1344 = normalize(half3(_668) + half3(_1206));
    half _1295 = clamp(dot(_652, half3(_1206)), half(0.0), half(1.0));
    half3 _1371 = cross(_652, _1344);
    half _1374 = clamp(dot(_652, _1344), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1391 = max(mix((half(2.0) * _1295) * _837, _1295 + _837, half(params.facet_alpha)), half(0.000244140625));
    half _1398 = _1145 / (fma(_1374, _1374, dot(_1371, _1371)) * (half(6433.98193359375) * _1391));
    half _1449 = half(1.0) - _837;
    half _1452 = _1449 * _1449;
    half _1469 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1479 = facet_environment.sample(facet_environmentSmplr, float3(_841), level(_1469 * (half(4.0) * (half(2.0) - _1469))));
    half3 _1443 = mix(fma(half4(_905).xyz, mix(half4(_876).xxx, half4(_876).yyy, half3(float3(params.facet_f0))) * _895, min(((half3(float3(params.facet_f0)) * min(_1150 * (_1150 * (half(6.283185482025146484375) * _1143)), half(65504.0))) * _895) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_967) * half(_967)) / fast::max(_953, 9.9999997473787516355514526367188e-05)) * half(_986)) * half(_986)), float3(65504.0))) * _1047), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1398 * (_1398 * (half(6.283185482025146484375) * _1391)), half(65504.0))) * _895) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1215) * half(_1215)) / fast::max(_1201, 9.9999997473787516355514526367188e-05)) * half(_1234)) * half(_1234)), float3(65504.0))) * _1295), half3(float3(65504.0))), half4(_1479).xyz, half3(fma(half(0.959999978542327880859375), (_1452 * _1452) * _1449, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1443, half(1.0)));
    return out;
}

