#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    half3 _803 = normalize(half3(in.v_normal));
    float3 _819 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1000 = max(dot(_803, half3(_819)), half(9.9999997473787516355514526367188e-05));
    half3 _1004 = reflect(-half3(_819), _803);
    float4 _1039 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1000, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1058 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1039).y) - half(1.0)));
    float4 _1065 = facet_environment.sample(facet_environmentSmplr, float3(_1004), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1138 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1098 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1000, _1138)), level(0.0));
    half3 _1145 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2441 = half4(_1098);
    half _1111 = _2441.z;
    half _1113 = fma(half(-float(max(_1145.x, max(_1145.y, _1145.z)))), _1111, half(1.0));
    half4 _2445 = half4(_1098);
    half _1115 = _2445.w;
    float4 _1152 = facet_environment.sample(facet_environmentSmplr, float3(_1004), level(_1138 * half(4.0)));
    half3 _865 = half4(frame.lightDirection).xyz;
    half3 _877 = half4(frame.lightColor).xyz;
    half3 _1283 = normalize(half3(_819) + _865);
    half _1231 = clamp(dot(_803, _865), half(0.0), half(1.0));
    half _1235 = clamp(dot(_803, _1283), half(0.0), half(1.0));
    half3 _1310 = cross(_803, _1283);
    half _1313 = _1235 * half(params.facet_alpha);
    half _1327 = _1231 + _1000;
    half _1330 = max(mix((half(2.0) * _1231) * _1000, _1327, half(params.facet_alpha)), half(0.000244140625));
    half _1332 = half(1024.0) * half(params.facet_alpha);
    half _1337 = _1332 / (fma(_1313, _1313, dot(_1310, _1310)) * (half(6433.98193359375) * _1330));
    half _1405 = _1138 * _1138;
    half _1425 = half(8192.0) * fma(half(-float(_1231)), _1000, _1327);
    half _1429 = half(1.0) / (_1405 * _1425);
    half _1436 = half(2048.0) * _1405;
    float3 _1506 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1509 = dot(_1506, _1506);
    float3 _1514 = _1506 * rsqrt(fast::max(_1509, 9.9999999392252902907785028219223e-09));
    float _1518 = _1509 * float(frame.punctualLights[0].positionFalloff.w);
    float _1523 = fast::clamp(fma(-_1518, _1518, 1.0), 0.0, 1.0);
    float _1542 = fast::clamp(fma(dot(-_1514, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1553 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1523) * half(_1523)) / fast::max(_1509, 9.9999997473787516355514526367188e-05)) * half(_1542)) * half(_1542)), float3(65504.0));
    half3 _1684 = normalize(half3(_819) + half3(_1514));
    half _1632 = clamp(dot(_803, half3(_1514)), half(0.0), half(1.0));
    half _1636 = clamp(dot(_803, _1684), half(0.0), half(1.0));
    half3 _1711 = cross(_803, _1684);
    half _1714 = _1636 * half(params.facet_alpha);
    half _1728 = _1632 + _1000;
    half _1731 = max(mix((half(2.0) * _1632) * _1000, _1728, half(params.facet_alpha)), half(0.000244140625));
    half _1738 = _1332 / (fma(_1714, _1714, dot(_1711, _1711)) * (half(6433.98193359375) * _1731));
    half _1826 = half(8192.0) * fma(half(-float(_1632)), _1000, _1728);
    half _1830 = half(1.0) / (_1405 * _1826);
    half3 _1871 = (fma(half4(_1152).xyz, _1145 * _1111, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1065).xyz * (mix(half4(_1039).xxx, half4(_1039).yyy, half3(float3(params.facet_f0))) * _1058)) * _1113) + (min(((half3(float3(params.facet_f0)) * min(_1337 * (_1337 * (half(6.283185482025146484375) * _1330)), half(65504.0))) * _1058) * ((_877 * _1231) * _1113), half3(float3(65504.0))) + min((_1145 * ((((fma(_1429, _1425, half(2.0)) * pow(max(fma(half(-float(_1235)), _1235, half(1.0)), half(0.0)), half(0.5) * (_1429 * _1425))) * half(0.15915493667125701904296875)) * (_1231 * (_1429 * _1436))) * _1115)) * _877, half3(float3(65504.0))))) + (min(((half3(float3(params.facet_f0)) * min(_1738 * (_1738 * (half(6.283185482025146484375) * _1731)), half(65504.0))) * _1058) * ((half3(_1553) * _1632) * _1113), half3(float3(65504.0))) + min((_1145 * ((((fma(_1830, _1826, half(2.0)) * pow(max(fma(half(-float(_1636)), _1636, half(1.0)), half(0.0)), half(0.5) * (_1830 * _1826))) * half(0.15915493667125701904296875)) * (_1632 * (_1830 * _1436))) * _1115)) * half3(_1553), half3(float3(65504.0))));
    float3 _1907 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1910 = dot(_1907, _1907);
    float3 _1915 = _1907 * rsqrt(fast::max(_1910, 9.9999999392252902907785028219223e-09));
    float _1919 = _1910 * float(frame.punctualLights[1].positionFalloff.w);
    float _1924 = fast::clamp(fma(-_1919, _1919, 1.0), 0.0, 1.0);
    float _1943 = fast::clamp(fma(dot(-_1915, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1954 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1924) * half(_1924)) / fast::max(_1910, 9.9999997473787516355514526367188e-05)) * half(_1943)) * half(_1943)), float3(65504.0));
    half3 _2085 = normalize(half3(_819) + half3(_1915));
    half _2033 = clamp(dot(_803, half3(_1915)), half(0.0), half(1.0));
    half _2037 = clamp(dot(_803, _2085), half(0.0), half(1.0));
    half3 _2112 = cross(_803, _2085);
    half _2115 = _2037 * half(params.facet_alpha);
    half _2129 = _2033 + _1000;
    half _2132 = max(mix((half(2.0) * _2033) * _1000, _2129, half(params.facet_alpha)), half(0.000244140625));
    half _2139 = _1332 / (fma(_2115, _2115, dot(_2112, _2112)) * (half(6433.98193359375) * _2132));
    half _2227 = half(8192.0) * fma(half(-float(_2033)), _1000, _2129);
    half _2231 = half(1.0) / (_1405 * _2227);
    out.fragColor = float4(half4(_1871 + (min(((half3(float3(params.facet_f0)) * min(_2139 * (_2139 * (half(6.283185482025146484375) * _2132)), half(65504.0))) * _1058) * ((half3(_1954) * _2033) * _1113), half3(float3(65504.0))) + min((_1145 * ((((fma(_2231, _2227, half(2.0)) * pow(max(fma(half(-float(_2037)), _2037, half(1.0)), half(0.0)), half(0.5) * (_2231 * _2227))) * half(0.15915493667125701904296875)) * (_2033 * (_2231 * _1436))) * _1115)) * half3(_1954), half3(float3(65504.0)))), half(1.0)));
    return out;
}

