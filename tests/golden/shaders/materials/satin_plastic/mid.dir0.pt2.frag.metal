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
    half3 _776 = normalize(half3(in.v_normal));
    float3 _792 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _952 = max(dot(_776, half3(_792)), half(9.9999997473787516355514526367188e-05));
    half3 _956 = reflect(-half3(_792), _776);
    float4 _991 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_952, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1010 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_991).y) - half(1.0)));
    float4 _1017 = facet_environment.sample(facet_environmentSmplr, float3(_956), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1094 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1051 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_952, _1094)), level(0.0));
    half3 _1101 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1952 = half4(_1051);
    half _1064 = _1952.z;
    half _1066 = fma(half(-float(max(_1101.x, max(_1101.y, _1101.z)))), _1064, half(1.0));
    half _1110 = _1094 * _1094;
    half4 _1956 = half4(_1051);
    half _1071 = _1956.w;
    float4 _1122 = facet_environment.sample(facet_environmentSmplr, float3(_956), level(_1094 * half(4.0)));
    float3 _1159 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1162 = dot(_1159, _1159);
    float3 _1167 = _1159 * rsqrt(fast::max(_1162, 9.9999999392252902907785028219223e-09));
    float _1171 = _1162 * float(frame.punctualLights[0].positionFalloff.w);
    float _1176 = fast::clamp(fma(-_1171, _1171, 1.0), 0.0, 1.0);
    float _1195 = fast::clamp(fma(dot(-_1167, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1206 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1176) * half(_1176)) / fast::max(_1162, 9.9999997473787516355514526367188e-05)) * half(_1195)) * half(_1195)), float3(65504.0));
    half3 _1322 = normalize(half3(_792) + half3(_1167));
    half _1261 = clamp(dot(_776, half3(_1167)), half(0.0), half(1.0));
    half _1265 = clamp(dot(_776, _1322), half(0.0), half(1.0));
    half3 _1385 = cross(_776, _1322) * half(64.0);
    half _1388 = half(64.0) * half(params.facet_alpha);
    half _1389 = _1265 * _1388;
    half _1360 = _1261 + _952;
    half _1365 = half(4096.0) * half(params.facet_alpha);
    half _1368 = half(6.283185482025146484375) * max(mix((half(2.0) * _1261) * _952, _1360, half(params.facet_alpha)), half(0.000244140625));
    half _1370 = _1365 / (fma(_1389, _1389, dot(_1385, _1385)) * _1368);
    half _1426 = half(8192.0) * fma(half(-float(_1261)), _952, _1360);
    half _1430 = half(1.0) / (_1110 * _1426);
    half _1437 = half(2048.0) * _1110;
    float3 _1495 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1498 = dot(_1495, _1495);
    float3 _1503 = _1495 * rsqrt(fast::max(_1498, 9.9999999392252902907785028219223e-09));
    float _1507 = _1498 * float(frame.punctualLights[1].positionFalloff.w);
    float _1512 = fast::clamp(fma(-_1507, _1507, 1.0), 0.0, 1.0);
    float _1531 = fast::clamp(fma(dot(-_1503, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1542 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1512) * half(_1512)) / fast::max(_1498, 9.9999997473787516355514526367188e-05)) * half(_1531)) * half(_1531)), float3(65504.0));
    half3 _1658 = normalize(half3(_792) + half3(_1503));
    half _1597 = clamp(dot(_776, half3(_1503)), half(0.0), half(1.0));
    half _1601 = clamp(dot(_776, _1658), half(0.0), half(1.0));
    half3 _1721 = cross(_776, _1658) * half(64.0);
    half _1725 = _1601 * _1388;
    half _1696 = _1597 + _952;
    half _1704 = half(6.283185482025146484375) * max(mix((half(2.0) * _1597) * _952, _1696, half(params.facet_alpha)), half(0.000244140625));
    half _1706 = _1365 / (fma(_1725, _1725, dot(_1721, _1721)) * _1704);
    half _1762 = half(8192.0) * fma(half(-float(_1597)), _952, _1696);
    half _1766 = half(1.0) / (_1110 * _1762);
    half3 _1795 = (fma(half4(_1122).xyz, _1101 * _1064, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1017).xyz * (mix(half4(_991).xxx, half4(_991).yyy, half3(float3(params.facet_f0))) * _1010)) * _1066) + min(fma((half3(float3(params.facet_f0)) * min(_1370 * (_1370 * _1368), half(65504.0))) * _1010, (half3(_1206) * _1261) * _1066, (_1101 * ((((fma(_1430, _1426, half(2.0)) * pow(max(fma(half(-float(_1265)), _1265, half(1.0)), half(0.0)), half(0.5) * (_1430 * _1426))) * half(0.15915493667125701904296875)) * (_1261 * (_1430 * _1437))) * _1071)) * half3(_1206)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1706 * (_1706 * _1704), half(65504.0))) * _1010, (half3(_1542) * _1597) * _1066, (_1101 * ((((fma(_1766, _1762, half(2.0)) * pow(max(fma(half(-float(_1601)), _1601, half(1.0)), half(0.0)), half(0.5) * (_1766 * _1762))) * half(0.15915493667125701904296875)) * (_1597 * (_1766 * _1437))) * _1071)) * half3(_1542)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1795, half(1.0)));
    return out;
}

