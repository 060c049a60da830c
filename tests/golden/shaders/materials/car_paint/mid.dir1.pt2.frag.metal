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
    half3 _645 = normalize(half3(in.v_normal));
    float3 _661 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _854 = max(dot(_645, half3(_661)), half(9.9999997473787516355514526367188e-05));
    half3 _858 = reflect(-half3(_661), _645);
    float4 _893 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_854, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _912 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_893).y) - half(1.0)));
    float4 _919 = facet_environment.sample(facet_environmentSmplr, float3(_858), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _699 = half4(frame.lightDirection).xyz;
    half3 _1026 = normalize(half3(_661) + _699);
    half _977 = clamp(dot(_645, _699), half(0.0), half(1.0));
    half3 _1053 = cross(_645, _1026);
    half _1056 = clamp(dot(_645, _1026), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1073 = max(mix((half(2.0) * _977) * _854, _977 + _854, half(params.facet_alpha)), half(0.000244140625));
    half _1075 = half(1024.0) * half(params.facet_alpha);
    half _1080 = _1075 / (fma(_1056, _1056, dot(_1053, _1053)) * (half(6433.98193359375) * _1073));
    float3 _1128 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1131 = dot(_1128, _1128);
    float3 _1136 = _1128 * rsqrt(fast::max(_1131, 9.9999999392252902907785028219223e-09));
    float _1140 = _1131 * float(frame.punctualLights[0].positionFalloff.w);
    float _1145 = fast::clamp(fma(-_1140, _1140, 1.0), 0.0, 1.0);
    float _1164 = fast::clamp(fma(dot(-_1136, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1274 = normalize(half3(_661) + half3(_1136));
    half _1225 = clamp(dot(_645, half3(_1136)), half(0.0), half(1.0));
    half3 _1301 = cross(_645, _1274);
    half _1304 = clamp(dot(_645, _1274), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1321 = max(mix((half(2.0) * _1225) * _854, _1225 + _854, half(params.facet_alpha)), half(0.000244140625));
    half _1328 = _1075 / (fma(_1304, _1304, dot(_1301, _1301)) * (half(6433.98193359375) * _1321));
    float3 _1376 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1379 = dot(_1376, _1376);
    float3 _1384 = _1376 * rsqrt(fast::max(_1379, 9.9999999392252902907785028219223e-09));
    float _1388 = _1379 * float(frame.punctualLights[1].positionFalloff.w);
    float _1393 = fast::clamp(fma(-_1388, _1388, 1.0), 0.0, 1.0);
    float _1412 = fast::clamp(fma(dot(-_1384, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1522 = normalize(half3(_661) + half3(_1384));
    half _1473 = clamp(dot(_645, half3(_1384)), half(0.0), half(1.0));
    half3 _1549 = cross(_645, _1522);
    half _1552 = clamp(dot(_645, _1522), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1569 = max(mix((half(2.0) * _1473) * _854, _1473 + _854, half(params.facet_alpha)), half(0.000244140625));
    half _1576 = _1075 / (fma(_1552, _1552, dot(_1549, _1549)) * (half(6433.98193359375) * _1569));
    half3 _1588 = (fma(half4(_919).xyz, mix(half4(_893).xxx, half4(_893).yyy, half3(float3(params.facet_f0))) * _912, min(((half3(float3(params.facet_f0)) * min(_1080 * (_1080 * (half(6.283185482025146484375) * _1073)), half(65504.0))) * _912) * (half4(frame.lightColor).xyz * _977), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1328 * (_1328 * (half(6.283185482025146484375) * _1321)), half(65504.0))) * _912) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1145) * half(_1145)) / fast::max(_1131, 9.9999997473787516355514526367188e-05)) * half(_1164)) * half(_1164)), float3(65504.0))) * _1225), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1576 * (_1576 * (half(6.283185482025146484375) * _1569)), half(65504.0))) * _912) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1393) * half(_1393)) / fast::max(_1379, 9.9999997473787516355514526367188e-05)) * half(_1412)) * half(_1412)), float3(65504.0))) * _1473), half3(float3(65504.0)));
    half _1625 = half(1.0) - _854;
    half _1628 = _1625 * _1625;
    float4 _1652 = facet_environment.sample(facet_environmentSmplr, float3(_858), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    out.fragColor = float4(half4(mix(_1588, half4(_1652).xyz, half3(fma(half(0.959999978542327880859375), (_1628 * _1628) * _1625, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

