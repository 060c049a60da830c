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
    half3 _774 = normalize(half3(in.v_normal));
    float3 _790 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _950 = max(dot(_774, half3(_790)), half(9.9999997473787516355514526367188e-05));
    half3 _954 = reflect(-half3(_790), _774);
    float4 _989 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_950, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1008 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_989).y) - half(1.0)));
    float4 _1015 = facet_environment.sample(facet_environmentSmplr, float3(_954), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1092 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1049 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_950, _1092)), level(0.0));
    half3 _1099 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1946 = half4(_1049);
    half _1062 = _1946.z;
    half _1064 = fma(half(-float(max(_1099.x, max(_1099.y, _1099.z)))), _1062, half(1.0));
    half _1108 = _1092 * _1092;
    half4 _1950 = half4(_1049);
    half _1069 = _1950.w;
    float4 _1120 = facet_environment.sample(facet_environmentSmplr, float3(_954), level(_1092 * half(4.0)));
    float3 _1157 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1160 = dot(_1157, _1157);
    float3 _1165 = _1157 * rsqrt(fast::max(_1160, 9.9999999392252902907785028219223e-09));
    float _1169 = _1160 * float(frame.punctualLights[0].positionFalloff.w);
    float _1174 = fast::clamp(fma(-_1169, _1169, 1.0), 0.0, 1.0);
    float _1193 = fast::clamp(fma(dot(-_1165, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1204 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1174) * half(_1174)) / fast::max(_1160, 9.9999997473787516355514526367188e-05)) * half(_1193)) * half(_1193)), float3(65504.0));
    half3 _1320 = normalize(half3(_790) + half3(_1165));
    half _1259 = clamp(dot(_774, half3(_1165)), half(0.0), half(1.0));
    half _1263 = clamp(dot(_774, _1320), half(0.0), half(1.0));
    half4 _1389 = half4(cross(_774, _1320), half(params.facet_alpha) * _1263) * half(64.0);
    half _1358 = _1259 + _950;
    half _1363 = half(4096.0) * half(params.facet_alpha);
    half _1366 = half(6.283185482025146484375) * max(mix((half(2.0) * _1259) * _950, _1358, half(params.facet_alpha)), half(0.000244140625));
    half _1368 = _1363 / (dot(_1389, _1389) * _1366);
    half _1422 = half(8192.0) * fma(half(-float(_1259)), _950, _1358);
    half _1426 = half(1.0) / (_1108 * _1422);
    half _1433 = half(2048.0) * _1108;
    float3 _1491 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1494 = dot(_1491, _1491);
    float3 _1499 = _1491 * rsqrt(fast::max(_1494, 9.9999999392252902907785028219223e-09));
    float _1503 = _1494 * float(frame.punctualLights[1].positionFalloff.w);
    float _1508 = fast::clamp(fma(-_1503, _1503, 1.0), 0.0, 1.0);
    float _1527 = fast::clamp(fma(dot(-_1499, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1538 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1508) * half(_1508)) / fast::max(_1494, 9.9999997473787516355514526367188e-05)) * half(_1527)) * half(_1527)), float3(65504.0));
    half3 _1654 = normalize(half3(_790) + half3(_1499));
    half _1593 = clamp(dot(_774, half3(_1499)), half(0.0), half(1.0));
    half _1597 = clamp(dot(_774, _1654), half(0.0), half(1.0));
    half4 _1723 = half4(cross(_774, _1654), half(params.facet_alpha) * _1597) * half(64.0);
    half _1692 = _1593 + _950;
    half _1700 = half(6.283185482025146484375) * max(mix((half(2.0) * _1593) * _950, _1692, half(params.facet_alpha)), half(0.000244140625));
    half _1702 = _1363 / (dot(_1723, _1723) * _1700);
    half _1756 = half(8192.0) * fma(half(-float(_1593)), _950, _1692);
    half _1760 = half(1.0) / (_1108 * _1756);
    half3 _1789 = (fma(half4(_1120).xyz, _1099 * _1062, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1015).xyz * (mix(half4(_989).xxx, half4(_989).yyy, half3(float3(params.facet_f0))) * _1008)) * _1064) + min(fma((half3(float3(params.facet_f0)) * min(_1368 * (_1368 * _1366), half(65504.0))) * _1008, (half3(_1204) * _1259) * _1064, (_1099 * ((((fma(_1426, _1422, half(2.0)) * pow(max(fma(half(-float(_1263)), _1263, half(1.0)), half(0.0)), half(0.5) * (_1426 * _1422))) * half(0.15915493667125701904296875)) * (_1259 * (_1426 * _1433))) * _1069)) * half3(_1204)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1702 * (_1702 * _1700), half(65504.0))) * _1008, (half3(_1538) * _1593) * _1064, (_1099 * ((((fma(_1760, _1756, half(2.0)) * pow(max(fma(half(-float(_1597)), _1597, half(1.0)), half(0.0)), half(0.5) * (_1760 * _1756))) * half(0.15915493667125701904296875)) * (_1593 * (_1760 * _1433))) * _1069)) * half3(_1538)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1789, half(1.0)));
    return out;
}

