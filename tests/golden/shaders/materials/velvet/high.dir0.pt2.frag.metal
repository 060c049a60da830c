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
    half3 _678 = normalize(half3(in.v_normal));
    float3 _684 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _820 = _678.y;
    half _825 = _678.z;
    half _830 = _678.x;
    half3 _898 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _820)) + (half4(frame.sh[2]).xyz * _825)) + (half4(frame.sh[3]).xyz * _830)) + (((((half4(frame.sh[4]).xyz * (_830 * _820)) + (half4(frame.sh[5]).xyz * (_820 * _825))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _825, _825, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_830 * _825))) + (half4(frame.sh[8]).xyz * fma(_830, _830, half(-float(_820 * _820))))), half3(float3(0.0)));
    half _939 = max(dot(_678, half3(_684)), half(9.9999997473787516355514526367188e-05));
    float4 _944 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_939, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _998 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1657 = half4(_944);
    half _957 = _1657.z;
    half _959 = fma(half(-float(max(_998.x, max(_998.y, _998.z)))), _957, half(1.0));
    half4 _1661 = half4(_944);
    half _964 = _1661.w;
    float4 _1019 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_684), _678)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1056 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1059 = dot(_1056, _1056);
    float3 _1064 = _1056 * rsqrt(fast::max(_1059, 9.9999999392252902907785028219223e-09));
    float _1068 = _1059 * float(frame.punctualLights[0].positionFalloff.w);
    float _1073 = fast::clamp(fma(-_1068, _1068, 1.0), 0.0, 1.0);
    float _1092 = fast::clamp(fma(dot(-_1064, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1126 = dot(_678, half3(_1064));
    half _1128 = clamp(_1126, half(0.0), half(1.0));
    half _1140 = clamp(dot(_678, half3(fast::normalize(_684 + _1064))), half(0.0), half(1.0));
    half _1211 = half(8192.0) * fma(half(-float(_1128)), _939, _1128 + _939);
    half _1215 = half(1.0) / (half(params.facet_alpha) * _1211);
    half _1222 = half(2048.0) * half(params.facet_alpha);
    half3 _1173 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1126 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1128), half3(float3(0.0)), half3(float3(1.0)))) * _959) + (_998 * ((((fma(_1215, _1211, half(2.0)) * pow(max(fma(half(-float(_1140)), _1140, half(1.0)), half(0.0)), half(0.5) * (_1215 * _1211))) * half(0.15915493667125701904296875)) * (_1128 * (_1215 * _1222))) * _964))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1073) * half(_1073)) / fast::max(_1059, 9.9999997473787516355514526367188e-05)) * half(_1092)) * half(_1092)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1286 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1289 = dot(_1286, _1286);
    float3 _1294 = _1286 * rsqrt(fast::max(_1289, 9.9999999392252902907785028219223e-09));
    float _1298 = _1289 * float(frame.punctualLights[1].positionFalloff.w);
    float _1303 = fast::clamp(fma(-_1298, _1298, 1.0), 0.0, 1.0);
    float _1322 = fast::clamp(fma(dot(-_1294, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1356 = dot(_678, half3(_1294));
    half _1358 = clamp(_1356, half(0.0), half(1.0));
    half _1370 = clamp(dot(_678, half3(fast::normalize(_684 + _1294))), half(0.0), half(1.0));
    half _1441 = half(8192.0) * fma(half(-float(_1358)), _939, _1358 + _939);
    half _1445 = half(1.0) / (half(params.facet_alpha) * _1441);
    half3 _1403 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1356 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1358), half3(float3(0.0)), half3(float3(1.0)))) * _959) + (_998 * ((((fma(_1445, _1441, half(2.0)) * pow(max(fma(half(-float(_1370)), _1370, half(1.0)), half(0.0)), half(0.5) * (_1445 * _1441))) * half(0.15915493667125701904296875)) * (_1358 * (_1445 * _1222))) * _964))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1303) * half(_1303)) / fast::max(_1289, 9.9999997473787516355514526367188e-05)) * half(_1322)) * half(_1322)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1019).xyz, _998 * _957, (half3(float3(params.facet_diffuseColor)) * _898) * _959) + _1173) + _1403, half(1.0)));
    return out;
}

