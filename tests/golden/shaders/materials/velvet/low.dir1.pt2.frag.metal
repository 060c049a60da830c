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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _487 = normalize(half3(in.v_normal));
    float3 _503 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _668 = max(dot(_487, half3(_503)), half(9.9999997473787516355514526367188e-05));
    float4 _673 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_668, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1370 = half4(_673);
    half _686 = _1370.z;
    half4 _1374 = half4(_673);
    half _693 = _1374.w;
    float4 _702 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_503), _487)), level(params.facet_sheenLod));
    half3 _538 = half4(frame.lightDirection).xyz;
    half _757 = clamp(dot(_487, _538), half(0.0), half(1.0));
    half _769 = clamp(dot(_487, normalize(half3(_503) + _538)), half(0.0), half(1.0));
    half _814 = half(8192.0) * fma(half(-float(_757)), _668, _757 + _668);
    half _818 = half(1.0) / (half(params.facet_alpha) * _814);
    half _825 = half(2048.0) * half(params.facet_alpha);
    float3 _883 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _886 = dot(_883, _883);
    float3 _891 = _883 * rsqrt(fast::max(_886, 9.9999999392252902907785028219223e-09));
    float _895 = _886 * float(frame.punctualLights[0].positionFalloff.w);
    float _900 = fast::clamp(fma(-_895, _895, 1.0), 0.0, 1.0);
    float _919 = fast::clamp(fma(dot(-_891, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _952 = clamp(dot(_487, half3(_891)), half(0.0), half(1.0));
    half _964 = clamp(dot(_487, normalize(half3(_503) + half3(_891))), half(0.0), half(1.0));
    half _1009 = half(8192.0) * fma(half(-float(_952)), _668, _952 + _668);
    half _1013 = half(1.0) / (half(params.facet_alpha) * _1009);
    half3 _1042 = (fma(half4(_702).xyz, half3(float3(params.facet_sheenColor)) * _686, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _686, half(1.0))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_818, _814, half(2.0)) * pow(max(fma(half(-float(_769)), _769, half(1.0)), half(0.0)), half(0.5) * (_818 * _814))) * half(0.15915493667125701904296875)) * (_757 * (_818 * _825))) * _693)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_1013, _1009, half(2.0)) * pow(max(fma(half(-float(_964)), _964, half(1.0)), half(0.0)), half(0.5) * (_1013 * _1009))) * half(0.15915493667125701904296875)) * (_952 * (_1013 * _825))) * _693)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_900) * half(_900)) / fast::max(_886, 9.9999997473787516355514526367188e-05)) * half(_919)) * half(_919)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1078 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1081 = dot(_1078, _1078);
    float3 _1086 = _1078 * rsqrt(fast::max(_1081, 9.9999999392252902907785028219223e-09));
    float _1090 = _1081 * float(frame.punctualLights[1].positionFalloff.w);
    float _1095 = fast::clamp(fma(-_1090, _1090, 1.0), 0.0, 1.0);
    float _1114 = fast::clamp(fma(dot(-_1086, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1147 = clamp(dot(_487, half3(_1086)), half(0.0), half(1.0));
    half _1159 = clamp(dot(_487, normalize(half3(_503) + half3(_1086))), half(0.0), half(1.0));
    half _1204 = half(8192.0) * fma(half(-float(_1147)), _668, _1147 + _668);
    half _1208 = half(1.0) / (half(params.facet_alpha) * _1204);
    out.fragColor = float4(half4(_1042 + min((half3(float3(params.facet_sheenColor)) * ((((fma(_1208, _1204, half(2.0)) * pow(max(fma(half(-float(_1159)), _1159, half(1.0)), half(0.0)), half(0.5) * (_1208 * _1204))) * half(0.15915493667125701904296875)) * (_1147 * (_1208 * _825))) * _693)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1095) * half(_1095)) / fast::max(_1081, 9.9999997473787516355514526367188e-05)) * half(_1114)) * half(_1114)), float3(65504.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

