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
    half3 _557 = normalize(half3(in.v_normal));
    float3 _573 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _742 = max(dot(_557, half3(_573)), half(9.9999997473787516355514526367188e-05));
    float4 _781 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_742, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _800 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_781).y) - half(1.0)));
    float4 _810 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_573), _557)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _610 = half4(frame.lightDirection).xyz;
    half3 _917 = normalize(half3(_573) + _610);
    half _868 = clamp(dot(_557, _610), half(0.0), half(1.0));
    half3 _944 = cross(_557, _917);
    half _947 = clamp(dot(_557, _917), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _964 = max(mix((half(2.0) * _868) * _742, _868 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _966 = half(1024.0) * half(params.facet_alpha);
    half _971 = _966 / (fma(_947, _947, dot(_944, _944)) * (half(6433.98193359375) * _964));
    float3 _1019 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1022 = dot(_1019, _1019);
    float3 _1027 = _1019 * rsqrt(fast::max(_1022, 9.9999999392252902907785028219223e-09));
    float _1031 = _1022 * float(frame.punctualLights[0].positionFalloff.w);
    float _1036 = fast::clamp(fma(-_1031, _1031, 1.0), 0.0, 1.0);
    float _1055 = fast::clamp(fma(dot(-_1027, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1165 = normalize(half3(_573) + half3(_1027));
    half _1116 = clamp(dot(_557, half3(_1027)), half(0.0), half(1.0));
    half3 _1192 = cross(_557, _1165);
    half _1195 = clamp(dot(_557, _1165), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1212 = max(mix((half(2.0) * _1116) * _742, _1116 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _1219 = _966 / (fma(_1195, _1195, dot(_1192, _1192)) * (half(6433.98193359375) * _1212));
    float3 _1267 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1270 = dot(_1267, _1267);
    float3 _1275 = _1267 * rsqrt(fast::max(_1270, 9.9999999392252902907785028219223e-09));
    float _1279 = _1270 * float(frame.punctualLights[1].positionFalloff.w);
    float _1284 = fast::clamp(fma(-_1279, _1279, 1.0), 0.0, 1.0);
    float _1303 = fast::clamp(fma(dot(-_1275, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1413 = normalize(half3(_573) + half3(_1275));
    half _1364 = clamp(dot(_557, half3(_1275)), half(0.0), half(1.0));
    half3 _1440 = cross(_557, _1413);
    half _1443 = clamp(dot(_557, _1413), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1460 = max(mix((half(2.0) * _1364) * _742, _1364 + _742, half(params.facet_alpha)), half(0.000244140625));
    half _1467 = _966 / (fma(_1443, _1443, dot(_1440, _1440)) * (half(6433.98193359375) * _1460));
    half3 _1479 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_810).xyz * (mix(half4(_781).xxx, half4(_781).yyy, half3(float3(params.facet_f0))) * _800)) + min(((half3(float3(params.facet_f0)) * min(_971 * (_971 * (half(6.283185482025146484375) * _964)), half(65504.0))) * _800) * (half4(frame.lightColor).xyz * _868), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1219 * (_1219 * (half(6.283185482025146484375) * _1212)), half(65504.0))) * _800) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1036) * half(_1036)) / fast::max(_1022, 9.9999997473787516355514526367188e-05)) * half(_1055)) * half(_1055)), float3(65504.0))) * _1116), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1467 * (_1467 * (half(6.283185482025146484375) * _1460)), half(65504.0))) * _800) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1284) * half(_1284)) / fast::max(_1270, 9.9999997473787516355514526367188e-05)) * half(_1303)) * half(_1303)), float3(65504.0))) * _1364), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1479, half(1.0)));
    return out;
}

