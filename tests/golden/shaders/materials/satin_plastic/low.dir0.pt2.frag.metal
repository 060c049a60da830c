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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _739 = normalize(half3(in.v_normal));
    float3 _755 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _918 = max(dot(_739, half3(_755)), half(9.9999997473787516355514526367188e-05));
    half3 _922 = reflect(-half3(_755), _739);
    float4 _958 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_918, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _984 = facet_environment.sample(facet_environmentSmplr, float3(_922), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _937 = mix(half4(_958).xxx, half4(_958).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_958).y) - half(1.0))));
    half _1061 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1018 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_918, _1061)), level(0.0));
    half3 _1068 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1853 = half4(_1018);
    half _1031 = _1853.z;
    half _1033 = fma(half(-float(max(_1068.x, max(_1068.y, _1068.z)))), _1031, half(1.0));
    half _1077 = _1061 * _1061;
    half4 _1857 = half4(_1018);
    half _1038 = _1857.w;
    float4 _1089 = facet_environment.sample(facet_environmentSmplr, float3(_922), level(_1061 * half(4.0)));
    float3 _1126 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1129 = dot(_1126, _1126);
    float3 _1134 = _1126 * rsqrt(fast::max(_1129, 9.9999999392252902907785028219223e-09));
    float _1138 = _1129 * float(frame.punctualLights[0].positionFalloff.w);
    float _1143 = fast::clamp(fma(-_1138, _1138, 1.0), 0.0, 1.0);
    float _1162 = fast::clamp(fma(dot(-_1134, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1173 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1143) * half(_1143)) / fast::max(_1129, 9.9999997473787516355514526367188e-05)) * half(_1162)) * half(_1162)), float3(65504.0));
    half _1228 = clamp(dot(_739, half3(_1134)), half(0.0), half(1.0));
    half _1232 = clamp(dot(_739, normalize(half3(_755) + half3(_1134))), half(0.0), half(1.0));
    half _1311 = clamp(dot(_922, half3(_1134)), half(0.0), half(1.0));
    half _1314 = _1311 * _1311;
    half4 _1887 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1314 * _1314, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1326 = _1887.x;
    half _1360 = half(8192.0) * fma(half(-float(_1228)), _918, _1228 + _918);
    half _1364 = half(1.0) / (_1077 * _1360);
    half _1371 = half(2048.0) * _1077;
    float3 _1429 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1432 = dot(_1429, _1429);
    float3 _1437 = _1429 * rsqrt(fast::max(_1432, 9.9999999392252902907785028219223e-09));
    float _1441 = _1432 * float(frame.punctualLights[1].positionFalloff.w);
    float _1446 = fast::clamp(fma(-_1441, _1441, 1.0), 0.0, 1.0);
    float _1465 = fast::clamp(fma(dot(-_1437, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1476 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1446) * half(_1446)) / fast::max(_1432, 9.9999997473787516355514526367188e-05)) * half(_1465)) * half(_1465)), float3(65504.0));
    half _1531 = clamp(dot(_739, half3(_1437)), half(0.0), half(1.0));
    half _1535 = clamp(dot(_739, normalize(half3(_755) + half3(_1437))), half(0.0), half(1.0));
    half _1614 = clamp(dot(_922, half3(_1437)), half(0.0), half(1.0));
    half _1617 = _1614 * _1614;
    half4 _1930 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1617 * _1617, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1629 = _1930.x;
    half _1663 = half(8192.0) * fma(half(-float(_1531)), _918, _1531 + _918);
    half _1667 = half(1.0) / (_1077 * _1663);
    half3 _1696 = (fma(half4(_1089).xyz, _1068 * _1031, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_984).xyz * _937) * _1033) + min(fma(_937 * ((_1326 * _1326) * half(5.092957973480224609375)), (half3(_1173) * _1228) * _1033, (_1068 * ((((fma(_1364, _1360, half(2.0)) * pow(max(fma(half(-float(_1232)), _1232, half(1.0)), half(0.0)), half(0.5) * (_1364 * _1360))) * half(0.15915493667125701904296875)) * (_1228 * (_1364 * _1371))) * _1038)) * half3(_1173)), half3(float3(65504.0)))) + min(fma(_937 * ((_1629 * _1629) * half(5.092957973480224609375)), (half3(_1476) * _1531) * _1033, (_1068 * ((((fma(_1667, _1663, half(2.0)) * pow(max(fma(half(-float(_1535)), _1535, half(1.0)), half(0.0)), half(0.5) * (_1667 * _1663))) * half(0.15915493667125701904296875)) * (_1531 * (_1667 * _1371))) * _1038)) * half3(_1476)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1696, half(1.0)));
    return out;
}

