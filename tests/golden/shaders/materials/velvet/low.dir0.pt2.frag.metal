#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _605 = normalize(half3(in.v_normal));
    float3 _611 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _802 = max(dot(_605, half3(_611)), half(9.9999997473787516355514526367188e-05));
    float4 _807 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_802, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _861 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1485 = half4(_807);
    half _820 = _1485.z;
    half _822 = fma(half(-float(max(_861.x, max(_861.y, _861.z)))), _820, half(1.0));
    half4 _1489 = half4(_807);
    half _827 = _1489.w;
    float4 _880 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_611), _605)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _917 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _920 = dot(_917, _917);
    float3 _925 = _917 * rsqrt(fast::max(_920, 9.9999999392252902907785028219223e-09));
    float _929 = _920 * float(frame.punctualLights[0].positionFalloff.w);
    float _934 = fast::clamp(fma(-_929, _929, 1.0), 0.0, 1.0);
    float _953 = fast::clamp(fma(dot(-_925, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _987 = dot(_605, half3(_925));
    half _989 = clamp(_987, half(0.0), half(1.0));
    half _1001 = clamp(dot(_605, normalize(half3(_611) + half3(_925))), half(0.0), half(1.0));
    half _1070 = half(8192.0) * fma(half(-float(_989)), _802, _989 + _802);
    half _1074 = half(1.0) / (half(params.facet_alpha) * _1070);
    half _1081 = half(2048.0) * half(params.facet_alpha);
    half3 _1034 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_987 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_989), half3(float3(0.0)), half3(float3(1.0)))) * _822) + (_861 * ((((fma(_1074, _1070, half(2.0)) * pow(max(fma(half(-float(_1001)), _1001, half(1.0)), half(0.0)), half(0.5) * (_1074 * _1070))) * half(0.15915493667125701904296875)) * (_989 * (_1074 * _1081))) * _827))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_934) * half(_934)) / fast::max(_920, 9.9999997473787516355514526367188e-05)) * half(_953)) * half(_953)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1145 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1148 = dot(_1145, _1145);
    float3 _1153 = _1145 * rsqrt(fast::max(_1148, 9.9999999392252902907785028219223e-09));
    float _1157 = _1148 * float(frame.punctualLights[1].positionFalloff.w);
    float _1162 = fast::clamp(fma(-_1157, _1157, 1.0), 0.0, 1.0);
    float _1181 = fast::clamp(fma(dot(-_1153, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1215 = dot(_605, half3(_1153));
    half _1217 = clamp(_1215, half(0.0), half(1.0));
    half _1229 = clamp(dot(_605, normalize(half3(_611) + half3(_1153))), half(0.0), half(1.0));
    half _1298 = half(8192.0) * fma(half(-float(_1217)), _802, _1217 + _802);
    half _1302 = half(1.0) / (half(params.facet_alpha) * _1298);
    half3 _1262 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1215 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1217), half3(float3(0.0)), half3(float3(1.0)))) * _822) + (_861 * ((((fma(_1302, _1298, half(2.0)) * pow(max(fma(half(-float(_1229)), _1229, half(1.0)), half(0.0)), half(0.5) * (_1302 * _1298))) * half(0.15915493667125701904296875)) * (_1217 * (_1302 * _1081))) * _827))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1162) * half(_1162)) / fast::max(_1148, 9.9999997473787516355514526367188e-05)) * half(_1181)) * half(_1181)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1337 = (fma(half4(_880).xyz, _861 * _820, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _605.y)) + (half4(frame.sh[2]).xyz * _605.z)) + (half4(frame.sh[3]).xyz * _605.x), half3(float3(0.0)))) * _822) + _1034) + _1262;
    out.fragColor = float4(half4(_1337, half(1.0)));
    return out;
}

