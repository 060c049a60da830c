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
    half3 _675 = normalize(half3(in.v_normal));
    float3 _691 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _860 = max(dot(_675, half3(_691)), half(9.9999997473787516355514526367188e-05));
    half3 _864 = reflect(-half3(_691), _675);
    float4 _899 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_860, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _918 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_899).y) - half(1.0)));
    float4 _928 = facet_environment.sample(facet_environmentSmplr, float3(_864), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _973 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _976 = dot(_973, _973);
    float3 _981 = _973 * rsqrt(fast::max(_976, 9.9999999392252902907785028219223e-09));
    float _985 = _976 * float(frame.punctualLights[0].positionFalloff.w);
    float _990 = fast::clamp(fma(-_985, _985, 1.0), 0.0, 1.0);
    float _1009 = fast::clamp(fma(dot(-_981, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1119 = normalize(half3(_691) + half3(_981));
    half _1070 = clamp(dot(_675, half3(_981)), half(0.0), half(1.0));
    half4 _1188 = half4(cross(_675, _1119), half(params.facet_alpha) * clamp(dot(_675, _1119), half(0.0), half(1.0))) * half(64.0);
    half _1162 = half(4096.0) * half(params.facet_alpha);
    half _1165 = half(6.283185482025146484375) * max(mix((half(2.0) * _1070) * _860, _1070 + _860, half(params.facet_alpha)), half(0.000244140625));
    half _1167 = _1162 / (dot(_1188, _1188) * _1165);
    float3 _1232 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1235 = dot(_1232, _1232);
    float3 _1240 = _1232 * rsqrt(fast::max(_1235, 9.9999999392252902907785028219223e-09));
    float _1244 = _1235 * float(frame.punctualLights[1].positionFalloff.w);
    float _1249 = fast::clamp(fma(-_1244, _1244, 1.0), 0.0, 1.0);
    float _1268 = fast::clamp(fma(dot(-_1240, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1378 = normalize(half3(_691) + half3(_1240));
    half _1329 = clamp(dot(_675, half3(_1240)), half(0.0), half(1.0));
    half4 _1447 = half4(cross(_675, _1378), half(params.facet_alpha) * clamp(dot(_675, _1378), half(0.0), half(1.0))) * half(64.0);
    half _1424 = half(6.283185482025146484375) * max(mix((half(2.0) * _1329) * _860, _1329 + _860, half(params.facet_alpha)), half(0.000244140625));
    half _1426 = _1162 / (dot(_1447, _1447) * _1424);
    half _1493 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1499 = half(1.0) - _860;
    half _1502 = _1499 * _1499;
    half _1518 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1528 = facet_environment.sample(facet_environmentSmplr, float3(_864), level(_1518 * (half(4.0) * (half(2.0) - _1518))));
    half3 _1488 = mix(fma(half4(_928).xyz, mix(half4(_899).xxx, half4(_899).yyy, half3(float3(params.facet_f0))) * _918, min(((half3(float3(params.facet_f0)) * min(_1167 * (_1167 * _1165), half(65504.0))) * _918) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_990) * half(_990)) / fast::max(_976, 9.9999997473787516355514526367188e-05)) * half(_1009)) * half(_1009)), float3(65504.0))) * _1070), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1426 * (_1426 * _1424), half(65504.0))) * _918) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1249) * half(_1249)) / fast::max(_1235, 9.9999997473787516355514526367188e-05)) * half(_1268)) * half(_1268)), float3(65504.0))) * _1329), half3(float3(65504.0))), half4(_1528).xyz, half3(fma(half(0.039999999105930328369140625), _1493, (half(0.959999978542327880859375) * _1493) * ((_1502 * _1502) * _1499))));
    out.fragColor = float4(half4(_1488, half(1.0)));
    return out;
}

