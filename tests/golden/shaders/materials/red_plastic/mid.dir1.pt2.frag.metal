#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _572 = normalize(half3(in.v_normal));
    float3 _588 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _757 = max(dot(_572, half3(_588)), half(9.9999997473787516355514526367188e-05));
    float4 _796 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_757, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _815 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_796).y) - half(1.0)));
    float4 _822 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_588), _572)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _625 = half4(frame.lightDirection).xyz;
    half3 _929 = normalize(half3(_588) + _625);
    half _880 = clamp(dot(_572, _625), half(0.0), half(1.0));
    half4 _998 = half4(cross(_572, _929), half(params.facet_alpha) * clamp(dot(_572, _929), half(0.0), half(1.0))) * half(64.0);
    half _972 = half(4096.0) * half(params.facet_alpha);
    half _975 = half(6.283185482025146484375) * max(mix((half(2.0) * _880) * _757, _880 + _757, half(params.facet_alpha)), half(0.000244140625));
    half _977 = _972 / (dot(_998, _998) * _975);
    float3 _1042 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1045 = dot(_1042, _1042);
    float3 _1050 = _1042 * rsqrt(fast::max(_1045, 9.9999999392252902907785028219223e-09));
    float _1054 = _1045 * float(frame.punctualLights[0].positionFalloff.w);
    float _1059 = fast::clamp(fma(-_1054, _1054, 1.0), 0.0, 1.0);
    float _1078 = fast::clamp(fma(dot(-_1050, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1188 = normalize(half3(_588) + half3(_1050));
    half _1139 = clamp(dot(_572, half3(_1050)), half(0.0), half(1.0));
    half4 _1257 = half4(cross(_572, _1188), half(params.facet_alpha) * clamp(dot(_572, _1188), half(0.0), half(1.0))) * half(64.0);
    half _1234 = half(6.283185482025146484375) * max(mix((half(2.0) * _1139) * _757, _1139 + _757, half(params.facet_alpha)), half(0.000244140625));
    half _1236 = _972 / (dot(_1257, _1257) * _1234);
    float3 _1301 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1304 = dot(_1301, _1301);
    float3 _1309 = _1301 * rsqrt(fast::max(_1304, 9.9999999392252902907785028219223e-09));
    float _1313 = _1304 * float(frame.punctualLights[1].positionFalloff.w);
    float _1318 = fast::clamp(fma(-_1313, _1313, 1.0), 0.0, 1.0);
    float _1337 = fast::clamp(fma(dot(-_1309, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1447 = normalize(half3(_588) + half3(_1309));
    half _1398 = clamp(dot(_572, half3(_1309)), half(0.0), half(1.0));
    half4 _1516 = half4(cross(_572, _1447), half(params.facet_alpha) * clamp(dot(_572, _1447), half(0.0), half(1.0))) * half(64.0);
    half _1493 = half(6.283185482025146484375) * max(mix((half(2.0) * _1398) * _757, _1398 + _757, half(params.facet_alpha)), half(0.000244140625));
    half _1495 = _972 / (dot(_1516, _1516) * _1493);
    half3 _1524 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_822).xyz * (mix(half4(_796).xxx, half4(_796).yyy, half3(float3(params.facet_f0))) * _815)) + min(((half3(float3(params.facet_f0)) * min(_977 * (_977 * _975), half(65504.0))) * _815) * (half4(frame.lightColor).xyz * _880), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1236 * (_1236 * _1234), half(65504.0))) * _815) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1059) * half(_1059)) / fast::max(_1045, 9.9999997473787516355514526367188e-05)) * half(_1078)) * half(_1078)), float3(65504.0))) * _1139), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1495 * (_1495 * _1493), half(65504.0))) * _815) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1318) * half(_1318)) / fast::max(_1304, 9.9999997473787516355514526367188e-05)) * half(_1337)) * half(_1337)), float3(65504.0))) * _1398), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1524, half(1.0)));
    return out;
}

