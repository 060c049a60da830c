#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _675 = normalize(half3(in.v_normal));
    float3 _691 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _812 = half4(in.v_tangent).xyz;
    half _865 = max(dot(_675, half3(_691)), half(9.9999997473787516355514526367188e-05));
    half _973 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1636;
    if (float(_973) >= 0.0)
    {
        _1636 = _812;
    }
    else
    {
        _1636 = cross(_675, _812);
    }
    half _925 = dot(_1636, half3(_691));
    half _932 = min(abs(_973) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _937 = fma(half(-float(_932)), half(1.0) - _865, half(1.0));
    half _940 = _932 * _925;
    float4 _980 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_865, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _999 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_980).y) - half(1.0)));
    float4 _1006 = facet_environment.sample(facet_environmentSmplr, float3(((((_675 * _937) + (_1636 * _940)) * (half(512.0) * fma(_937, _865, _940 * _925))) - (half3(_691) * (half(256.0) * fma(_937, _937, _940 * _940))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1051 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1054 = dot(_1051, _1051);
    float3 _1059 = _1051 * rsqrt(fast::max(_1054, 9.9999999392252902907785028219223e-09));
    float _1063 = _1054 * float(frame.punctualLights[0].positionFalloff.w);
    float _1068 = fast::clamp(fma(-_1063, _1063, 1.0), 0.0, 1.0);
    float _1087 = fast::clamp(fma(dot(-_1059, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1197 = normalize(half3(_691) + half3(_1059));
    half _1148 = clamp(dot(_675, half3(_1059)), half(0.0), half(1.0));
    half3 _1224 = cross(_675, _1197);
    half _1227 = clamp(dot(_675, _1197), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1244 = max(mix((half(2.0) * _1148) * _865, _1148 + _865, half(params.facet_alpha)), half(0.000244140625));
    half _1246 = half(1024.0) * half(params.facet_alpha);
    half _1251 = _1246 / (fma(_1227, _1227, dot(_1224, _1224)) * (half(6433.98193359375) * _1244));
    float3 _1299 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1302 = dot(_1299, _1299);
    float3 _1307 = _1299 * rsqrt(fast::max(_1302, 9.9999999392252902907785028219223e-09));
    float _1311 = _1302 * float(frame.punctualLights[1].positionFalloff.w);
    float _1316 = fast::clamp(fma(-_1311, _1311, 1.0), 0.0, 1.0);
    float _1335 = fast::clamp(fma(dot(-_1307, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1445 = normalize(half3(_691) + half3(_1307));
    half _1396 = clamp(dot(_675, half3(_1307)), half(0.0), half(1.0));
    half3 _1472 = cross(_675, _1445);
    half _1475 = clamp(dot(_675, _1445), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1492 = max(mix((half(2.0) * _1396) * _865, _1396 + _865, half(params.facet_alpha)), half(0.000244140625));
    half _1499 = _1246 / (fma(_1475, _1475, dot(_1472, _1472)) * (half(6433.98193359375) * _1492));
    half3 _1511 = fma(half4(_1006).xyz, mix(half4(_980).xxx, half4(_980).yyy, half3(float3(params.facet_f0))) * _999, min(((half3(float3(params.facet_f0)) * min(_1251 * (_1251 * (half(6.283185482025146484375) * _1244)), half(65504.0))) * _999) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1068) * half(_1068)) / fast::max(_1054, 9.9999997473787516355514526367188e-05)) * half(_1087)) * half(_1087)), float3(65504.0))) * _1148), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1499 * (_1499 * (half(6.283185482025146484375) * _1492)), half(65504.0))) * _999) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1316) * half(_1316)) / fast::max(_1302, 9.9999997473787516355514526367188e-05)) * half(_1335)) * half(_1335)), float3(65504.0))) * _1396), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1511, half(1.0)));
    return out;
}

