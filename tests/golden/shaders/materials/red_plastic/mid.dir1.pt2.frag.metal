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
    half _742 = max(dot(_554, half3(_570)), half(9.9999997473787516355514526367188e-05));
    float4 _781 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_742, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _800 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_781).y) - half(1.0)));
    float4 _807 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_570), _554)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _607 = half4(frame.lightDirection).xyz;
    half3 _914 = normalize(half3(_570) + _607);
    half _865 = clamp(dot(_554, _607), half(0.0), half(1.0));
    half3 _941 = cross(_554, _914);
    half _944 = clamp(dot(_554, _914), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _961 = max(mix((half(2.0) * _865) * _742, _865 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _963 = half(1024.0) * half(params.facet_alpha);
    half _968 = _963 / (fma(_944, _944, dot(_941, _941)) * (half(6433.98193359375) * _961));
    float3 _1016 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1019 = dot(_1016, _1016);
    float3 _1024 = _1016 * rsqrt(fast::max(_1019, 9.9999999392252902907785028219223e-09));
    float _1028 = _1019 * float(frame.punctualLights[0].positionFalloff.w);
    float _1033 = fast::clamp(fma(-_1028, _1028, 1.0), 0.0, 1.0);
    float _1052 = fast::clamp(fma(dot(-_1024, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1162 = normalize(half3(_570) + half3(_1024));
    half _1113 = clamp(dot(_554, half3(_1024)), half(0.0), half(1.0));
    half3 _1189 = cross(_554, _1162);
    half _1192 = clamp(dot(_554, _1162), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1209 = max(mix((half(2.0) * _1113) * _742, _1113 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _1216 = _963 / (fma(_1192, _1192, dot(_1189, _1189)) * (half(6433.98193359375) * _1209));
    float3 _1264 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1267 = dot(_1264, _1264);
    float3 _1272 = _1264 * rsqrt(fast::max(_1267, 9.9999999392252902907785028219223e-09));
    float _1276 = _1267 * float(frame.punctualLights[1].positionFalloff.w);
    float _1281 = fast::clamp(fma(-_1276, _1276, 1.0), 0.0, 1.0);
    float _1300 = fast::clamp(fma(dot(-_1272, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1410 = normalize(half3(_570) + half3(_1272));
    half _1361 = clamp(dot(_554, half3(_1272)), half(0.0), half(1.0));
    half3 _1437 = cross(_554, _1410);
    half _1440 = clamp(dot(_554, _1410), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1457 = max(mix((half(2.0) * _1361) * _742, _1361 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _1464 = _963 / (fma(_1440, _1440, dot(_1437, _1437)) * (half(6433.98193359375) * _1457));
    half3 _1476 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_807).xyz * (mix(half4(_781).xxx, half4(_781).yyy, half3(float3(params.facet_f0))) * _800)) + min(((half3(float3(params.facet_f0)) * min(_968 * (_968 * (half(6.283185482025146484375) * _961)), half(65504.0))) * _800) * (half4(frame.lightColor).xyz * _865), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1216 * (_1216 * (half(6.283185482025146484375) * _1209)), half(65504.0))) * _800) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1033) * half(_1033)) / fast::max(_1019, 9.9999997473787516355514526367188e-05)) * half(_1052)) * half(_1052)), float3(65504.0))) * _1113), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1464 * (_1464 * (half(6.283185482025146484375) * _1457)), half(65504.0))) * _800) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1281) * half(_1281)) / fast::max(_1267, 9.9999997473787516355514526367188e-05)) * half(_1300)) * half(_1300)), float3(65504.0))) * _1361), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1476, half(1.0)));
    return out;
}

