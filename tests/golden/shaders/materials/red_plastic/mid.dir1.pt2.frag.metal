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
    half3 _574 = normalize(half3(in.v_normal));
    float3 _590 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _759 = max(dot(_574, half3(_590)), half(9.9999997473787516355514526367188e-05));
    float4 _798 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_759, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _817 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_798).y) - half(1.0)));
    float4 _824 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_590), _574)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _627 = half4(frame.lightDirection).xyz;
    half3 _931 = normalize(half3(_590) + _627);
    half _882 = clamp(dot(_574, _627), half(0.0), half(1.0));
    half3 _994 = cross(_574, _931) * half(64.0);
    half _997 = half(64.0) * half(params.facet_alpha);
    half _998 = clamp(dot(_574, _931), half(0.0), half(1.0)) * _997;
    half _974 = half(4096.0) * half(params.facet_alpha);
    half _977 = half(6.283185482025146484375) * max(mix((half(2.0) * _882) * _759, _882 + _759, half(params.facet_alpha)), half(0.000244140625));
    half _979 = _974 / (fma(_998, _998, dot(_994, _994)) * _977);
    float3 _1046 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1049 = dot(_1046, _1046);
    float3 _1054 = _1046 * rsqrt(fast::max(_1049, 9.9999999392252902907785028219223e-09));
    float _1058 = _1049 * float(frame.punctualLights[0].positionFalloff.w);
    float _1063 = fast::clamp(fma(-_1058, _1058, 1.0), 0.0, 1.0);
    float _1082 = fast::clamp(fma(dot(-_1054, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1192 = normalize(half3(_590) + half3(_1054));
    half _1143 = clamp(dot(_574, half3(_1054)), half(0.0), half(1.0));
    half3 _1255 = cross(_574, _1192) * half(64.0);
    half _1259 = clamp(dot(_574, _1192), half(0.0), half(1.0)) * _997;
    half _1238 = half(6.283185482025146484375) * max(mix((half(2.0) * _1143) * _759, _1143 + _759, half(params.facet_alpha)), half(0.000244140625));
    half _1240 = _974 / (fma(_1259, _1259, dot(_1255, _1255)) * _1238);
    float3 _1307 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1310 = dot(_1307, _1307);
    float3 _1315 = _1307 * rsqrt(fast::max(_1310, 9.9999999392252902907785028219223e-09));
    float _1319 = _1310 * float(frame.punctualLights[1].positionFalloff.w);
    float _1324 = fast::clamp(fma(-_1319, _1319, 1.0), 0.0, 1.0);
    float _1343 = fast::clamp(fma(dot(-_1315, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1453 = normalize(half3(_590) + half3(_1315));
    half _1404 = clamp(dot(_574, half3(_1315)), half(0.0), half(1.0));
    half3 _1516 = cross(_574, _1453) * half(64.0);
    half _1520 = clamp(dot(_574, _1453), half(0.0), half(1.0)) * _997;
    half _1499 = half(6.283185482025146484375) * max(mix((half(2.0) * _1404) * _759, _1404 + _759, half(params.facet_alpha)), half(0.000244140625));
    half _1501 = _974 / (fma(_1520, _1520, dot(_1516, _1516)) * _1499);
    half3 _1532 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_824).xyz * (mix(half4(_798).xxx, half4(_798).yyy, half3(float3(params.facet_f0))) * _817)) + min(((half3(float3(params.facet_f0)) * min(_979 * (_979 * _977), half(65504.0))) * _817) * (half4(frame.lightColor).xyz * _882), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1240 * (_1240 * _1238), half(65504.0))) * _817) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1063) * half(_1063)) / fast::max(_1049, 9.9999997473787516355514526367188e-05)) * half(_1082)) * half(_1082)), float3(65504.0))) * _1143), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1501 * (_1501 * _1499), half(65504.0))) * _817) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1324) * half(_1324)) / fast::max(_1310, 9.9999997473787516355514526367188e-05)) * half(_1343)) * half(_1343)), float3(65504.0))) * _1404), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1532, half(1.0)));
    return out;
}

