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
    half3 _777 = normalize(half3(in.v_normal));
    float3 _793 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _974 = max(dot(_777, half3(_793)), half(9.9999997473787516355514526367188e-05));
    half3 _978 = reflect(-half3(_793), _777);
    float4 _1013 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_974, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1032 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1013).y) - half(1.0)));
    float4 _1042 = facet_environment.sample(facet_environmentSmplr, float3(_978), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1119 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1076 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_974, _1119)), level(0.0));
    half3 _1126 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2230 = half4(_1076);
    half _1089 = _2230.z;
    half _1091 = fma(half(-float(max(_1126.x, max(_1126.y, _1126.z)))), _1089, half(1.0));
    half _1135 = _1119 * _1119;
    half4 _2234 = half4(_1076);
    half _1096 = _2234.w;
    float4 _1150 = facet_environment.sample(facet_environmentSmplr, float3(_978), level(_1119 * (half(4.0) * (half(2.0) - _1119))));
    half3 _839 = half4(frame.lightDirection).xyz;
    half3 _851 = half4(frame.lightColor).xyz;
    half3 _1266 = normalize(half3(_793) + _839);
    half _1205 = clamp(dot(_777, _839), half(0.0), half(1.0));
    half _1209 = clamp(dot(_777, _1266), half(0.0), half(1.0));
    half4 _1335 = half4(cross(_777, _1266), half(params.facet_alpha) * _1209) * half(64.0);
    half _1304 = _1205 + _974;
    half _1309 = half(4096.0) * half(params.facet_alpha);
    half _1312 = half(6.283185482025146484375) * max(mix((half(2.0) * _1205) * _974, _1304, half(params.facet_alpha)), half(0.000244140625));
    half _1314 = _1309 / (dot(_1335, _1335) * _1312);
    half _1368 = half(8192.0) * fma(half(-float(_1205)), _974, _1304);
    half _1372 = half(1.0) / (_1135 * _1368);
    half _1379 = half(2048.0) * _1135;
    float3 _1437 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1440 = dot(_1437, _1437);
    float3 _1445 = _1437 * rsqrt(fast::max(_1440, 9.9999999392252902907785028219223e-09));
    float _1449 = _1440 * float(frame.punctualLights[0].positionFalloff.w);
    float _1454 = fast::clamp(fma(-_1449, _1449, 1.0), 0.0, 1.0);
    float _1473 = fast::clamp(fma(dot(-_1445, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1484 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1454) * half(_1454)) / fast::max(_1440, 9.9999997473787516355514526367188e-05)) * half(_1473)) * half(_1473)), float3(65504.0));
    half3 _1600 = normalize(half3(_793) + half3(_1445));
    half _1539 = clamp(dot(_777, half3(_1445)), half(0.0), half(1.0));
    half _1543 = clamp(dot(_777, _1600), half(0.0), half(1.0));
    half4 _1669 = half4(cross(_777, _1600), half(params.facet_alpha) * _1543) * half(64.0);
    half _1638 = _1539 + _974;
    half _1646 = half(6.283185482025146484375) * max(mix((half(2.0) * _1539) * _974, _1638, half(params.facet_alpha)), half(0.000244140625));
    half _1648 = _1309 / (dot(_1669, _1669) * _1646);
    half _1702 = half(8192.0) * fma(half(-float(_1539)), _974, _1638);
    half _1706 = half(1.0) / (_1135 * _1702);
    half3 _1735 = (fma(half4(_1150).xyz, _1126 * _1089, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1042).xyz * (mix(half4(_1013).xxx, half4(_1013).yyy, half3(float3(params.facet_f0))) * _1032)) * _1091) + min(fma((half3(float3(params.facet_f0)) * min(_1314 * (_1314 * _1312), half(65504.0))) * _1032, (_851 * _1205) * _1091, (_1126 * ((((fma(_1372, _1368, half(2.0)) * pow(max(fma(half(-float(_1209)), _1209, half(1.0)), half(0.0)), half(0.5) * (_1372 * _1368))) * half(0.15915493667125701904296875)) * (_1205 * (_1372 * _1379))) * _1096)) * _851), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1648 * (_1648 * _1646), half(65504.0))) * _1032, (half3(_1484) * _1539) * _1091, (_1126 * ((((fma(_1706, _1702, half(2.0)) * pow(max(fma(half(-float(_1543)), _1543, half(1.0)), half(0.0)), half(0.5) * (_1706 * _1702))) * half(0.15915493667125701904296875)) * (_1539 * (_1706 * _1379))) * _1096)) * half3(_1484)), half3(float3(65504.0)));
    float3 _1771 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1774 = dot(_1771, _1771);
    float3 _1779 = _1771 * rsqrt(fast::max(_1774, 9.9999999392252902907785028219223e-09));
    float _1783 = _1774 * float(frame.punctualLights[1].positionFalloff.w);
    float _1788 = fast::clamp(fma(-_1783, _1783, 1.0), 0.0, 1.0);
    float _1807 = fast::clamp(fma(dot(-_1779, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1818 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1788) * half(_1788)) / fast::max(_1774, 9.9999997473787516355514526367188e-05)) * half(_1807)) * half(_1807)), float3(65504.0));
    half3 _1934 = normalize(half3(_793) + half3(_1779));
    half _1873 = clamp(dot(_777, half3(_1779)), half(0.0), half(1.0));
    half _1877 = clamp(dot(_777, _1934), half(0.0), half(1.0));
    half4 _2003 = half4(cross(_777, _1934), half(params.facet_alpha) * _1877) * half(64.0);
    half _1972 = _1873 + _974;
    half _1980 = half(6.283185482025146484375) * max(mix((half(2.0) * _1873) * _974, _1972, half(params.facet_alpha)), half(0.000244140625));
    half _1982 = _1309 / (dot(_2003, _2003) * _1980);
    half _2036 = half(8192.0) * fma(half(-float(_1873)), _974, _1972);
    half _2040 = half(1.0) / (_1135 * _2036);
    out.fragColor = float4(half4(_1735 + min(fma((half3(float3(params.facet_f0)) * min(_1982 * (_1982 * _1980), half(65504.0))) * _1032, (half3(_1818) * _1873) * _1091, (_1126 * ((((fma(_2040, _2036, half(2.0)) * pow(max(fma(half(-float(_1877)), _1877, half(1.0)), half(0.0)), half(0.5) * (_2040 * _2036))) * half(0.15915493667125701904296875)) * (_1873 * (_2040 * _1379))) * _1096)) * half3(_1818)), half3(float3(65504.0))), half(1.0)));
    return out;
}

