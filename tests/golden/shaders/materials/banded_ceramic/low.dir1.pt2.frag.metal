#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _620 = normalize(half3(in.v_normal));
    float3 _636 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _785 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _894 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _785)), half(0.0), half(1.0));
    half3 _902 = half3((half(0.1599999964237213134765625) * _894) * _894);
    half _911 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _785)), half(0.08900000154972076416015625), half(1.0));
    half3 _857 = reflect(-half3(_636), _620);
    float4 _918 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_620, half3(_636)), half(9.9999997473787516355514526367188e-05)), _911)), level(0.0));
    float4 _947 = facet_environment.sample(facet_environmentSmplr, float3(_857), level(_911 * (half(4.0) * (half(2.0) - _911))));
    half3 _872 = mix(half4(_918).xxx, half4(_918).yyy, _902) * (half3(float3(1.0)) + (_902 * ((half(1.0) / half4(_918).y) - half(1.0))));
    half3 _673 = half4(frame.lightDirection).xyz;
    half _1111 = clamp(dot(_857, _673), half(0.0), half(1.0));
    half _1114 = _1111 * _1111;
    half4 _1838 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1114 * _1114, _911), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1126 = _1838.x;
    float3 _1171 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1174 = dot(_1171, _1171);
    float3 _1179 = _1171 * rsqrt(fast::max(_1174, 9.9999999392252902907785028219223e-09));
    float _1183 = _1174 * float(frame.punctualLights[0].positionFalloff.w);
    float _1188 = fast::clamp(fma(-_1183, _1183, 1.0), 0.0, 1.0);
    float _1207 = fast::clamp(fma(dot(-_1179, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1374 = clamp(dot(_857, half3(_1179)), half(0.0), half(1.0));
    half _1377 = _1374 * _1374;
    half4 _1862 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1377 * _1377, _911), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1389 = _1862.x;
    float3 _1434 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1437 = dot(_1434, _1434);
    float3 _1442 = _1434 * rsqrt(fast::max(_1437, 9.9999999392252902907785028219223e-09));
    float _1446 = _1437 * float(frame.punctualLights[1].positionFalloff.w);
    float _1451 = fast::clamp(fma(-_1446, _1446, 1.0), 0.0, 1.0);
    float _1470 = fast::clamp(fma(dot(-_1442, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1637 = clamp(dot(_857, half3(_1442)), half(0.0), half(1.0));
    half _1640 = _1637 * _1637;
    half4 _1887 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1640 * _1640, _911), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1652 = _1887.x;
    half3 _1661 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_785))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_947).xyz * _872) + min((_872 * ((_1126 * _1126) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_620, _673), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_872 * ((_1389 * _1389) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1188) * half(_1188)) / fast::max(_1174, 9.9999997473787516355514526367188e-05)) * half(_1207)) * half(_1207)), float3(65504.0))) * clamp(dot(_620, half3(_1179)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_872 * ((_1652 * _1652) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1451) * half(_1451)) / fast::max(_1437, 9.9999997473787516355514526367188e-05)) * half(_1470)) * half(_1470)), float3(65504.0))) * clamp(dot(_620, half3(_1442)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1661, half(1.0)));
    return out;
}

