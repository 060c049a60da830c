#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    half3 _557 = normalize(half3(in.v_normal));
    float3 _573 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _726 = max(dot(_557, half3(_573)), half(9.9999997473787516355514526367188e-05));
    float4 _765 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_726, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _784 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_765).y) - half(1.0)));
    float4 _791 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_573), _557)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _836 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _839 = dot(_836, _836);
    float3 _844 = _836 * rsqrt(fast::max(_839, 9.9999999392252902907785028219223e-09));
    float _848 = _839 * float(frame.punctualLights[0].positionFalloff.w);
    float _853 = fast::clamp(fma(-_848, _848, 1.0), 0.0, 1.0);
    float _872 = fast::clamp(fma(dot(-_844, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _982 = normalize(half3(_573) + half3(_844));
    half _933 = clamp(dot(_557, half3(_844)), half(0.0), half(1.0));
    half3 _1009 = cross(_557, _982);
    half _1012 = clamp(dot(_557, _982), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1029 = max(mix((half(2.0) * _933) * _726, _933 + _726, half(params.facet_alpha)), half(0.000244140625));
    half _1031 = half(1024.0) * half(params.facet_alpha);
    half _1036 = _1031 / (fma(_1012, _1012, dot(_1009, _1009)) * (half(6433.98193359375) * _1029));
    float3 _1084 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1087 = dot(_1084, _1084);
    float3 _1092 = _1084 * rsqrt(fast::max(_1087, 9.9999999392252902907785028219223e-09));
    float _1096 = _1087 * float(frame.punctualLights[1].positionFalloff.w);
    float _1101 = fast::clamp(fma(-_1096, _1096, 1.0), 0.0, 1.0);
    float _1120 = fast::clamp(fma(dot(-_1092, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1230 = normalize(half3(_573) + half3(_1092));
    half _1181 = clamp(dot(_557, half3(_1092)), half(0.0), half(1.0));
    half3 _1257 = cross(_557, _1230);
    half _1260 = clamp(dot(_557, _1230), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1277 = max(mix((half(2.0) * _1181) * _726, _1181 + _726, half(params.facet_alpha)), half(0.000244140625));
    half _1284 = _1031 / (fma(_1260, _1260, dot(_1257, _1257)) * (half(6433.98193359375) * _1277));
    half3 _1296 = fma(half4(_791).xyz, mix(half4(_765).xxx, half4(_765).yyy, half3(float3(params.facet_f0))) * _784, min(((half3(float3(params.facet_f0)) * min(_1036 * (_1036 * (half(6.283185482025146484375) * _1029)), half(65504.0))) * _784) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_853) * half(_853)) / fast::max(_839, 9.9999997473787516355514526367188e-05)) * half(_872)) * half(_872)), float3(65504.0))) * _933), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1284 * (_1284 * (half(6.283185482025146484375) * _1277)), half(65504.0))) * _784) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1101) * half(_1101)) / fast::max(_1087, 9.9999997473787516355514526367188e-05)) * half(_1120)) * half(_1120)), float3(65504.0))) * _1181), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1296, half(1.0)));
    return out;
}

