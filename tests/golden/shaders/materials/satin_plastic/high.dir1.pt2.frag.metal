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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _770 = normalize(half3(in.v_normal));
    float3 _786 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _964 = max(dot(_770, half3(_786)), half(9.9999997473787516355514526367188e-05));
    half3 _968 = reflect(-half3(_786), _770);
    float4 _1000 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_964, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _979 = facet_environment.sample(facet_environmentSmplr, float3(_968), level(params.facet_environmentLod));
    float4 _1040 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_964, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2244 = half4(_1040);
    half _1053 = _2244.z;
    half _1055 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1053, half(1.0));
    half4 _2248 = half4(_1040);
    half _1060 = _2248.w;
    float4 _1069 = facet_environment.sample(facet_environmentSmplr, float3(_968), level(params.facet_sheenLod));
    half3 _844 = half4(frame.lightColor).xyz;
    half _1144 = clamp(dot(_770, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1206 = fast::normalize(_786 + frame.lightDirection.xyz);
    half _1151 = clamp(dot(_770, half3(_1206)), half(0.0), half(1.0));
    half _1246 = half(4096.0) * half(params.facet_alpha);
    half4 _1271 = half4(cross(_770, half3(_1206)), half(params.facet_alpha) * _1151) * half(64.0);
    half _1252 = _1246 / dot(_1271, _1271);
    half _1284 = _1144 + _964;
    half _1296 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1206)), half(0.0), half(1.0));
    half _1299 = _1296 * _1296;
    half3 _1307 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1340 = half(8192.0) * fma(half(-float(_1144)), _964, _1284);
    half _1344 = half(1.0) / (half(params.facet_sheenAlpha) * _1340);
    half _1351 = half(2048.0) * half(params.facet_sheenAlpha);
    half3 _1187 = min(fma((half3(float3(params.facet_f0)) + (_1307 * ((_1299 * _1299) * _1296))) * min(min((_1252 * _1252) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1144) * _964, _1284, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (_844 * _1144) * _1055, (half3(float3(params.facet_sheenColor)) * ((((fma(_1344, _1340, half(2.0)) * pow(max(fma(half(-float(_1151)), _1151, half(1.0)), half(0.0)), half(0.5) * (_1344 * _1340))) * half(0.15915493667125701904296875)) * (_1144 * (_1344 * _1351))) * _1060)) * _844), half3(float3(65504.0)));
    float3 _1409 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1412 = dot(_1409, _1409);
    float3 _1417 = _1409 * rsqrt(fast::max(_1412, 9.9999999392252902907785028219223e-09));
    float _1421 = _1412 * float(frame.punctualLights[0].positionFalloff.w);
    float _1426 = fast::clamp(fma(-_1421, _1421, 1.0), 0.0, 1.0);
    float _1445 = fast::clamp(fma(dot(-_1417, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1456 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1426) * half(_1426)) / fast::max(_1412, 9.9999997473787516355514526367188e-05)) * half(_1445)) * half(_1445)), float3(65504.0));
    half _1508 = clamp(dot(_770, half3(_1417)), half(0.0), half(1.0));
    float3 _1570 = fast::normalize(_786 + _1417);
    half _1515 = clamp(dot(_770, half3(_1570)), half(0.0), half(1.0));
    half4 _1635 = half4(cross(_770, half3(_1570)), half(params.facet_alpha) * _1515) * half(64.0);
    half _1616 = _1246 / dot(_1635, _1635);
    half _1648 = _1508 + _964;
    half _1660 = half(1.0) - clamp(dot(half3(_1417), half3(_1570)), half(0.0), half(1.0));
    half _1663 = _1660 * _1660;
    half _1704 = half(8192.0) * fma(half(-float(_1508)), _964, _1648);
    half _1708 = half(1.0) / (half(params.facet_sheenAlpha) * _1704);
    half3 _1551 = min(fma((half3(float3(params.facet_f0)) + (_1307 * ((_1663 * _1663) * _1660))) * min(min((_1616 * _1616) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1508) * _964, _1648, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1456) * _1508) * _1055, (half3(float3(params.facet_sheenColor)) * ((((fma(_1708, _1704, half(2.0)) * pow(max(fma(half(-float(_1515)), _1515, half(1.0)), half(0.0)), half(0.5) * (_1708 * _1704))) * half(0.15915493667125701904296875)) * (_1508 * (_1708 * _1351))) * _1060)) * half3(_1456)), half3(float3(65504.0)));
    float3 _1773 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1776 = dot(_1773, _1773);
    float3 _1781 = _1773 * rsqrt(fast::max(_1776, 9.9999999392252902907785028219223e-09));
    float _1785 = _1776 * float(frame.punctualLights[1].positionFalloff.w);
    float _1790 = fast::clamp(fma(-_1785, _1785, 1.0), 0.0, 1.0);
    float _1809 = fast::clamp(fma(dot(-_1781, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1820 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1790) * half(_1790)) / fast::max(_1776, 9.9999997473787516355514526367188e-05)) * half(_1809)) * half(_1809)), float3(65504.0));
    half _1872 = clamp(dot(_770, half3(_1781)), half(0.0), half(1.0));
    float3 _1934 = fast::normalize(_786 + _1781);
    half _1879 = clamp(dot(_770, half3(_1934)), half(0.0), half(1.0));
    half4 _1999 = half4(cross(_770, half3(_1934)), half(params.facet_alpha) * _1879) * half(64.0);
    half _1980 = _1246 / dot(_1999, _1999);
    half _2012 = _1872 + _964;
    half _2024 = half(1.0) - clamp(dot(half3(_1781), half3(_1934)), half(0.0), half(1.0));
    half _2027 = _2024 * _2024;
    half _2068 = half(8192.0) * fma(half(-float(_1872)), _964, _2012);
    half _2072 = half(1.0) / (half(params.facet_sheenAlpha) * _2068);
    half3 _1915 = min(fma((half3(float3(params.facet_f0)) + (_1307 * ((_2027 * _2027) * _2024))) * min(min((_1980 * _1980) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1872) * _964, _2012, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1820) * _1872) * _1055, (half3(float3(params.facet_sheenColor)) * ((((fma(_2072, _2068, half(2.0)) * pow(max(fma(half(-float(_1879)), _1879, half(1.0)), half(0.0)), half(0.5) * (_2072 * _2068))) * half(0.15915493667125701904296875)) * (_1872 * (_2072 * _1351))) * _1060)) * half3(_1820)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1069).xyz, half3(float3(params.facet_sheenColor)) * _1053, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_979).xyz * mix(half4(_1000).xxx, half4(_1000).yyy, half3(float3(params.facet_f0)))) * _1055) + _1187) + _1551) + _1915, half(1.0)));
    return out;
}

