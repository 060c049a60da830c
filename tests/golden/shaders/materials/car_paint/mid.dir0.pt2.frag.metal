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
    half3 _654 = normalize(half3(in.v_normal));
    float3 _670 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _839 = max(dot(_654, half3(_670)), half(9.9999997473787516355514526367188e-05));
    half3 _843 = reflect(-half3(_670), _654);
    float4 _878 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_839, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _897 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_878).y) - half(1.0)));
    float4 _909 = facet_environment.sample(facet_environmentSmplr, float3(_843), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _954 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _957 = dot(_954, _954);
    float3 _962 = _954 * rsqrt(fast::max(_957, 9.9999999392252902907785028219223e-09));
    float _966 = _957 * float(frame.punctualLights[0].positionFalloff.w);
    float _971 = fast::clamp(fma(-_966, _966, 1.0), 0.0, 1.0);
    float _990 = fast::clamp(fma(dot(-_962, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1100 = normalize(half3(_670) + half3(_962));
    half _1051 = clamp(dot(_654, half3(_962)), half(0.0), half(1.0));
    half3 _1127 = cross(_654, _1100);
    half _1130 = clamp(dot(_654, _1100), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1147 = max(mix((half(2.0) * _1051) * _839, _1051 + _839, half(params.facet_alpha)), half(0.000244140625));
    half _1149 = half(1024.0) * half(params.facet_alpha);
    half _1154 = _1149 / (fma(_1130, _1130, dot(_1127, _1127)) * (half(6433.98193359375) * _1147));
    float3 _1202 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1205 = dot(_1202, _1202);
    float3 _1210 = _1202 * rsqrt(fast::max(_1205, 9.9999999392252902907785028219223e-09));
    float _1214 = _1205 * float(frame.punctualLights[1].positionFalloff.w);
    float _1219 = fast::clamp(fma(-_1214, _1214, 1.0), 0.0, 1.0);
    float _1238 = fast::clamp(fma(dot(-_1210, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1348 = normalize(half3(_670) + half3(_1210));
    half _1299 = clamp(dot(_654, half3(_1210)), half(0.0), half(1.0));
    half3 _1375 = cross(_654, _1348);
    half _1378 = clamp(dot(_654, _1348), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1395 = max(mix((half(2.0) * _1299) * _839, _1299 + _839, half(params.facet_alpha)), half(0.000244140625));
    half _1402 = _1149 / (fma(_1378, _1378, dot(_1375, _1375)) * (half(6433.98193359375) * _1395));
    half _1453 = half(1.0) - _839;
    half _1456 = _1453 * _1453;
    half _1473 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1485 = facet_environment.sample(facet_environmentSmplr, float3(_843), level(_1473 * (half(4.0) * (half(2.0) - _1473))));
    half3 _1447 = mix(fma(half4(_909).xyz, mix(half4(_878).xxx, half4(_878).yyy, half3(float3(params.facet_f0))) * _897, min(((half3(float3(params.facet_f0)) * min(_1154 * (_1154 * (half(6.283185482025146484375) * _1147)), half(65504.0))) * _897) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_971) * half(_971)) / fast::max(_957, 9.9999997473787516355514526367188e-05)) * half(_990)) * half(_990)), float3(65504.0))) * _1051), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1402 * (_1402 * (half(6.283185482025146484375) * _1395)), half(65504.0))) * _897) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1219) * half(_1219)) / fast::max(_1205, 9.9999997473787516355514526367188e-05)) * half(_1238)) * half(_1238)), float3(65504.0))) * _1299), half3(float3(65504.0))), half4(_1485).xyz, half3(fma(half(0.959999978542327880859375), (_1456 * _1456) * _1453, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1447, half(1.0)));
    return out;
}

