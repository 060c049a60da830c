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
    half _968 = max(dot(_770, half3(_786)), half(9.9999997473787516355514526367188e-05));
    half3 _972 = reflect(-half3(_786), _770);
    float4 _1007 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_968, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1026 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1007).y) - half(1.0)));
    float4 _1036 = facet_environment.sample(facet_environmentSmplr, float3(_972), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1068 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_968, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2192 = half4(_1068);
    half _1081 = _2192.z;
    half _1083 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1081, half(1.0));
    half4 _2196 = half4(_1068);
    half _1088 = _2196.w;
    float4 _1097 = facet_environment.sample(facet_environmentSmplr, float3(_972), level(params.facet_sheenLod));
    half3 _832 = half4(frame.lightDirection).xyz;
    half3 _844 = half4(frame.lightColor).xyz;
    half3 _1236 = normalize(half3(_786) + _832);
    half _1175 = clamp(dot(_770, _832), half(0.0), half(1.0));
    half _1179 = clamp(dot(_770, _1236), half(0.0), half(1.0));
    half4 _1305 = half4(cross(_770, _1236), half(params.facet_alpha) * _1179) * half(64.0);
    half _1274 = _1175 + _968;
    half _1279 = half(4096.0) * half(params.facet_alpha);
    half _1282 = half(6.283185482025146484375) * max(mix((half(2.0) * _1175) * _968, _1274, half(params.facet_alpha)), half(0.000244140625));
    half _1284 = _1279 / (dot(_1305, _1305) * _1282);
    half _1338 = half(8192.0) * fma(half(-float(_1175)), _968, _1274);
    half _1342 = half(1.0) / (half(params.facet_sheenAlpha) * _1338);
    half _1349 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1407 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1410 = dot(_1407, _1407);
    float3 _1415 = _1407 * rsqrt(fast::max(_1410, 9.9999999392252902907785028219223e-09));
    float _1419 = _1410 * float(frame.punctualLights[0].positionFalloff.w);
    float _1424 = fast::clamp(fma(-_1419, _1419, 1.0), 0.0, 1.0);
    float _1443 = fast::clamp(fma(dot(-_1415, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1454 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1424) * half(_1424)) / fast::max(_1410, 9.9999997473787516355514526367188e-05)) * half(_1443)) * half(_1443)), float3(65504.0));
    half3 _1570 = normalize(half3(_786) + half3(_1415));
    half _1509 = clamp(dot(_770, half3(_1415)), half(0.0), half(1.0));
    half _1513 = clamp(dot(_770, _1570), half(0.0), half(1.0));
    half4 _1639 = half4(cross(_770, _1570), half(params.facet_alpha) * _1513) * half(64.0);
    half _1608 = _1509 + _968;
    half _1616 = half(6.283185482025146484375) * max(mix((half(2.0) * _1509) * _968, _1608, half(params.facet_alpha)), half(0.000244140625));
    half _1618 = _1279 / (dot(_1639, _1639) * _1616);
    half _1672 = half(8192.0) * fma(half(-float(_1509)), _968, _1608);
    half _1676 = half(1.0) / (half(params.facet_sheenAlpha) * _1672);
    half3 _1705 = (fma(half4(_1097).xyz, half3(float3(params.facet_sheenColor)) * _1081, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1036).xyz * (mix(half4(_1007).xxx, half4(_1007).yyy, half3(float3(params.facet_f0))) * _1026)) * _1083) + min(fma((half3(float3(params.facet_f0)) * min(_1284 * (_1284 * _1282), half(65504.0))) * _1026, (_844 * _1175) * _1083, (half3(float3(params.facet_sheenColor)) * ((((fma(_1342, _1338, half(2.0)) * pow(max(fma(half(-float(_1179)), _1179, half(1.0)), half(0.0)), half(0.5) * (_1342 * _1338))) * half(0.15915493667125701904296875)) * (_1175 * (_1342 * _1349))) * _1088)) * _844), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1618 * (_1618 * _1616), half(65504.0))) * _1026, (half3(_1454) * _1509) * _1083, (half3(float3(params.facet_sheenColor)) * ((((fma(_1676, _1672, half(2.0)) * pow(max(fma(half(-float(_1513)), _1513, half(1.0)), half(0.0)), half(0.5) * (_1676 * _1672))) * half(0.15915493667125701904296875)) * (_1509 * (_1676 * _1349))) * _1088)) * half3(_1454)), half3(float3(65504.0)));
    float3 _1741 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1744 = dot(_1741, _1741);
    float3 _1749 = _1741 * rsqrt(fast::max(_1744, 9.9999999392252902907785028219223e-09));
    float _1753 = _1744 * float(frame.punctualLights[1].positionFalloff.w);
    float _1758 = fast::clamp(fma(-_1753, _1753, 1.0), 0.0, 1.0);
    float _1777 = fast::clamp(fma(dot(-_1749, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1788 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1758) * half(_1758)) / fast::max(_1744, 9.9999997473787516355514526367188e-05)) * half(_1777)) * half(_1777)), float3(65504.0));
    half3 _1904 = normalize(half3(_786) + half3(_1749));
    half _1843 = clamp(dot(_770, half3(_1749)), half(0.0), half(1.0));
    half _1847 = clamp(dot(_770, _1904), half(0.0), half(1.0));
    half4 _1973 = half4(cross(_770, _1904), half(params.facet_alpha) * _1847) * half(64.0);
    half _1942 = _1843 + _968;
    half _1950 = half(6.283185482025146484375) * max(mix((half(2.0) * _1843) * _968, _1942, half(params.facet_alpha)), half(0.000244140625));
    half _1952 = _1279 / (dot(_1973, _1973) * _1950);
    half _2006 = half(8192.0) * fma(half(-float(_1843)), _968, _1942);
    half _2010 = half(1.0) / (half(params.facet_sheenAlpha) * _2006);
    out.fragColor = float4(half4(_1705 + min(fma((half3(float3(params.facet_f0)) * min(_1952 * (_1952 * _1950), half(65504.0))) * _1026, (half3(_1788) * _1843) * _1083, (half3(float3(params.facet_sheenColor)) * ((((fma(_2010, _2006, half(2.0)) * pow(max(fma(half(-float(_1847)), _1847, half(1.0)), half(0.0)), half(0.5) * (_2010 * _2006))) * half(0.15915493667125701904296875)) * (_1843 * (_2010 * _1349))) * _1088)) * half3(_1788)), half3(float3(65504.0))), half(1.0)));
    return out;
}

