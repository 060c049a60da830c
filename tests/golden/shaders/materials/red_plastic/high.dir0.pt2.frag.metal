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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _761 = normalize(half3(in.v_normal));
    float3 _767 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _901 = _761.y;
    half _906 = _761.z;
    half _911 = _761.x;
    half3 _979 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _901)) + (half4(frame.sh[2]).xyz * _906)) + (half4(frame.sh[3]).xyz * _911)) + (((((half4(frame.sh[4]).xyz * (_911 * _901)) + (half4(frame.sh[5]).xyz * (_901 * _906))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _906, _906, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_911 * _906))) + (half4(frame.sh[8]).xyz * fma(_911, _911, half(-float(_901 * _901))))), half3(float3(0.0)));
    half _1029 = max(dot(_761, half3(_767)), half(9.9999997473787516355514526367188e-05));
    float4 _1068 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1029, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1087 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1068).y) - half(1.0)));
    float4 _1094 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_767), _761)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1139 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1142 = dot(_1139, _1139);
    float3 _1147 = _1139 * rsqrt(fast::max(_1142, 9.9999999392252902907785028219223e-09));
    float _1151 = _1142 * float(frame.punctualLights[0].positionFalloff.w);
    float _1156 = fast::clamp(fma(-_1151, _1151, 1.0), 0.0, 1.0);
    float _1175 = fast::clamp(fma(dot(-_1147, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1294 = fast::normalize(_767 + _1147);
    half _1238 = clamp(dot(_761, half3(_1147)), half(0.0), half(1.0));
    half3 _1334 = cross(_761, half3(_1294));
    half _1337 = clamp(dot(_761, half3(_1294)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1346 = half(params.facet_alpha) / fma(_1337, _1337, dot(_1334, _1334));
    half _1360 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1366 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1370 = sqrt(fma(_1029 * _1029, _1366, _1360));
    half _1394 = half(1.0) - clamp(dot(half3(_1147), half3(_1294)), half(0.0), half(1.0));
    half _1397 = _1394 * _1394;
    half3 _1405 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1269 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1455 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1458 = dot(_1455, _1455);
    float3 _1463 = _1455 * rsqrt(fast::max(_1458, 9.9999999392252902907785028219223e-09));
    float _1467 = _1458 * float(frame.punctualLights[1].positionFalloff.w);
    float _1472 = fast::clamp(fma(-_1467, _1467, 1.0), 0.0, 1.0);
    float _1491 = fast::clamp(fma(dot(-_1463, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1610 = fast::normalize(_767 + _1463);
    half _1554 = clamp(dot(_761, half3(_1463)), half(0.0), half(1.0));
    half3 _1650 = cross(_761, half3(_1610));
    half _1653 = clamp(dot(_761, half3(_1610)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1662 = half(params.facet_alpha) / fma(_1653, _1653, dot(_1650, _1650));
    half _1710 = half(1.0) - clamp(dot(half3(_1463), half3(_1610)), half(0.0), half(1.0));
    half _1713 = _1710 * _1710;
    half3 _1735 = (fma(half3(float3(params.facet_diffuseColor)), _979, half4(_1094).xyz * (mix(half4(_1068).xxx, half4(_1068).yyy, half3(float3(params.facet_f0))) * _1087)) + min(fma((half3(float3(params.facet_f0)) + (_1405 * ((_1397 * _1397) * _1394))) * min(min((_1346 * _1346) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1238, _1370, _1029 * sqrt(fma(_1238 * _1238, _1366, _1360))), half(65504.0)), half(65504.0)), _1087, _1269) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1156) * half(_1156)) / fast::max(_1142, 9.9999997473787516355514526367188e-05)) * half(_1175)) * half(_1175)), float3(65504.0))) * _1238), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1405 * ((_1713 * _1713) * _1710))) * min(min((_1662 * _1662) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1554, _1370, _1029 * sqrt(fma(_1554 * _1554, _1366, _1360))), half(65504.0)), half(65504.0)), _1087, _1269) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1472) * half(_1472)) / fast::max(_1458, 9.9999997473787516355514526367188e-05)) * half(_1491)) * half(_1491)), float3(65504.0))) * _1554), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1735, half(1.0)));
    return out;
}

