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
    half3 _554 = normalize(half3(in.v_normal));
    float3 _570 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _739 = max(dot(_554, half3(_570)), half(9.9999997473787516355514526367188e-05));
    float4 _778 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_739, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _797 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_778).y) - half(1.0)));
    float4 _804 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_570), _554)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _607 = half4(frame.lightDirection).xyz;
    half3 _911 = normalize(half3(_570) + _607);
    half _862 = clamp(dot(_554, _607), half(0.0), half(1.0));
    half3 _938 = cross(_554, _911);
    half _941 = clamp(dot(_554, _911), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _958 = max(mix((half(2.0) * _862) * _739, _862 + _739, half(params.facet_alpha)), half(0.000244140625));
    half _960 = half(1024.0) * half(params.facet_alpha);
    half _965 = _960 / (fma(_941, _941, dot(_938, _938)) * (half(6433.98193359375) * _958));
    float3 _1013 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1016 = dot(_1013, _1013);
    float3 _1021 = _1013 * rsqrt(fast::max(_1016, 9.9999999392252902907785028219223e-09));
    float _1025 = _1016 * float(frame.punctualLights[0].positionFalloff.w);
    float _1030 = fast::clamp(fma(-_1025, _1025, 1.0), 0.0, 1.0);
    float _1049 = fast::clamp(fma(dot(-_1021, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1159 = normalize(half3(_570) + half3(_1021));
    half _1110 = clamp(dot(_554, half3(_1021)), half(0.0), half(1.0));
    half3 _1186 = cross(_554, _1159);
    half _1189 = clamp(dot(_554, _1159), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1206 = max(mix((half(2.0) * _1110) * _739, _1110 + _739, half(params.facet_alpha)), half(0.000244140625));
    half _1213 = _960 / (fma(_1189, _1189, dot(_1186, _1186)) * (half(6433.98193359375) * _1206));
    float3 _1261 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1264 = dot(_1261, _1261);
    float3 _1269 = _1261 * rsqrt(fast::max(_1264, 9.9999999392252902907785028219223e-09));
    float _1273 = _1264 * float(frame.punctualLights[1].positionFalloff.w);
    float _1278 = fast::clamp(fma(-_1273, _1273, 1.0), 0.0, 1.0);
    float _1297 = fast::clamp(fma(dot(-_1269, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1407 = normalize(half3(_570) + half3(_1269));
    half _1358 = clamp(dot(_554, half3(_1269)), half(0.0), half(1.0));
    half3 _1434 = cross(_554, _1407);
    half _1437 = clamp(dot(_554, _1407), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1454 = max(mix((half(2.0) * _1358) * _739, _1358 + _739, half(params.facet_alpha)), half(0.000244140625));
    half _1461 = _960 / (fma(_1437, _1437, dot(_1434, _1434)) * (half(6433.98193359375) * _1454));
    half3 _1473 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_804).xyz * (mix(half4(_778).xxx, half4(_778).yyy, half3(float3(params.facet_f0))) * _797)) + min(((half3(float3(params.facet_f0)) * min(_965 * (_965 * (half(6.283185482025146484375) * _958)), half(65504.0))) * _797) * (half4(frame.lightColor).xyz * _862), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1213 * (_1213 * (half(6.283185482025146484375) * _1206)), half(65504.0))) * _797) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1030) * half(_1030)) / fast::max(_1016, 9.9999997473787516355514526367188e-05)) * half(_1049)) * half(_1049)), float3(65504.0))) * _1110), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1461 * (_1461 * (half(6.283185482025146484375) * _1454)), half(65504.0))) * _797) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1278) * half(_1278)) / fast::max(_1264, 9.9999997473787516355514526367188e-05)) * half(_1297)) * half(_1297)), float3(65504.0))) * _1358), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1473, half(1.0)));
    return out;
}

