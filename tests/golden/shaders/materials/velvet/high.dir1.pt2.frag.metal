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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _657 = normalize(half3(in.v_normal));
    float3 _663 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _820 = _657.y;
    half _825 = _657.z;
    half _830 = _657.x;
    half3 _898 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _820)) + (half4(frame.sh[2]).xyz * _825)) + (half4(frame.sh[3]).xyz * _830)) + (((((half4(frame.sh[4]).xyz * (_830 * _820)) + (half4(frame.sh[5]).xyz * (_820 * _825))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _825, _825, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_830 * _825))) + (half4(frame.sh[8]).xyz * fma(_830, _830, half(-float(_820 * _820))))), half3(float3(0.0)));
    half _937 = max(dot(_657, half3(_663)), half(9.9999997473787516355514526367188e-05));
    float4 _942 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_937, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1805 = half4(_942);
    half _955 = _1805.z;
    half _957 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _955, half(1.0));
    half4 _1809 = half4(_942);
    half _962 = _1809.w;
    float4 _971 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_663), _657)), level(params.facet_sheenLod));
    half _1027 = dot(_657, half3(frame.lightDirection.xyz));
    half _1029 = clamp(_1027, half(0.0), half(1.0));
    half _1041 = clamp(dot(_657, half3(fast::normalize(_663 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1112 = half(8192.0) * fma(half(-float(_1029)), _937, _1029 + _937);
    half _1116 = half(1.0) / (half(params.facet_alpha) * _1112);
    half _1123 = half(2048.0) * half(params.facet_alpha);
    float3 _1187 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1190 = dot(_1187, _1187);
    float3 _1195 = _1187 * rsqrt(fast::max(_1190, 9.9999999392252902907785028219223e-09));
    float _1199 = _1190 * float(frame.punctualLights[0].positionFalloff.w);
    float _1204 = fast::clamp(fma(-_1199, _1199, 1.0), 0.0, 1.0);
    float _1223 = fast::clamp(fma(dot(-_1195, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1257 = dot(_657, half3(_1195));
    half _1259 = clamp(_1257, half(0.0), half(1.0));
    half _1271 = clamp(dot(_657, half3(fast::normalize(_663 + _1195))), half(0.0), half(1.0));
    half _1342 = half(8192.0) * fma(half(-float(_1259)), _937, _1259 + _937);
    half _1346 = half(1.0) / (half(params.facet_alpha) * _1342);
    half3 _1304 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1257 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1259), half3(float3(0.0)), half3(float3(1.0)))) * _957) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1346, _1342, half(2.0)) * pow(max(fma(half(-float(_1271)), _1271, half(1.0)), half(0.0)), half(0.5) * (_1346 * _1342))) * half(0.15915493667125701904296875)) * (_1259 * (_1346 * _1123))) * _962))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1204) * half(_1204)) / fast::max(_1190, 9.9999997473787516355514526367188e-05)) * half(_1223)) * half(_1223)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1381 = (fma(half4(_971).xyz, half3(float3(params.facet_sheenColor)) * _955, (half3(float3(params.facet_diffuseColor)) * _898) * _957) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1027 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1029), half3(float3(0.0)), half3(float3(1.0)))) * _957) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1116, _1112, half(2.0)) * pow(max(fma(half(-float(_1041)), _1041, half(1.0)), half(0.0)), half(0.5) * (_1116 * _1112))) * half(0.15915493667125701904296875)) * (_1029 * (_1116 * _1123))) * _962))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1304;
    float3 _1417 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1420 = dot(_1417, _1417);
    float3 _1425 = _1417 * rsqrt(fast::max(_1420, 9.9999999392252902907785028219223e-09));
    float _1429 = _1420 * float(frame.punctualLights[1].positionFalloff.w);
    float _1434 = fast::clamp(fma(-_1429, _1429, 1.0), 0.0, 1.0);
    float _1453 = fast::clamp(fma(dot(-_1425, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1487 = dot(_657, half3(_1425));
    half _1489 = clamp(_1487, half(0.0), half(1.0));
    half _1501 = clamp(dot(_657, half3(fast::normalize(_663 + _1425))), half(0.0), half(1.0));
    half _1572 = half(8192.0) * fma(half(-float(_1489)), _937, _1489 + _937);
    half _1576 = half(1.0) / (half(params.facet_alpha) * _1572);
    half3 _1534 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1487 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1489), half3(float3(0.0)), half3(float3(1.0)))) * _957) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1576, _1572, half(2.0)) * pow(max(fma(half(-float(_1501)), _1501, half(1.0)), half(0.0)), half(0.5) * (_1576 * _1572))) * half(0.15915493667125701904296875)) * (_1489 * (_1576 * _1123))) * _962))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1434) * half(_1434)) / fast::max(_1420, 9.9999997473787516355514526367188e-05)) * half(_1453)) * half(_1453)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1381 + _1534, half(1.0)));
    return out;
}

