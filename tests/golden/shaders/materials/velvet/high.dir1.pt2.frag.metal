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
    half3 _676 = normalize(half3(in.v_normal));
    float3 _682 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _839 = _676.y;
    half _844 = _676.z;
    half _849 = _676.x;
    half3 _917 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _839)) + (half4(frame.sh[2]).xyz * _844)) + (half4(frame.sh[3]).xyz * _849)) + (((((half4(frame.sh[4]).xyz * (_849 * _839)) + (half4(frame.sh[5]).xyz * (_839 * _844))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _844, _844, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_849 * _844))) + (half4(frame.sh[8]).xyz * fma(_849, _849, half(-float(_839 * _839))))), half3(float3(0.0)));
    half _958 = max(dot(_676, half3(_682)), half(9.9999997473787516355514526367188e-05));
    float4 _963 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_958, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1017 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1839 = half4(_963);
    half _976 = _1839.z;
    half _978 = fma(half(-float(max(_1017.x, max(_1017.y, _1017.z)))), _976, half(1.0));
    half4 _1843 = half4(_963);
    half _983 = _1843.w;
    float4 _1036 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_682), _676)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1059 = dot(_676, half3(frame.lightDirection.xyz));
    half _1061 = clamp(_1059, half(0.0), half(1.0));
    half _1073 = clamp(dot(_676, half3(fast::normalize(_682 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1144 = half(8192.0) * fma(half(-float(_1061)), _958, _1061 + _958);
    half _1148 = half(1.0) / (half(params.facet_alpha) * _1144);
    half _1155 = half(2048.0) * half(params.facet_alpha);
    float3 _1219 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1222 = dot(_1219, _1219);
    float3 _1227 = _1219 * rsqrt(fast::max(_1222, 9.9999999392252902907785028219223e-09));
    float _1231 = _1222 * float(frame.punctualLights[0].positionFalloff.w);
    float _1236 = fast::clamp(fma(-_1231, _1231, 1.0), 0.0, 1.0);
    float _1255 = fast::clamp(fma(dot(-_1227, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1289 = dot(_676, half3(_1227));
    half _1291 = clamp(_1289, half(0.0), half(1.0));
    half _1303 = clamp(dot(_676, half3(fast::normalize(_682 + _1227))), half(0.0), half(1.0));
    half _1374 = half(8192.0) * fma(half(-float(_1291)), _958, _1291 + _958);
    half _1378 = half(1.0) / (half(params.facet_alpha) * _1374);
    half3 _1336 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1289 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1291), half3(float3(0.0)), half3(float3(1.0)))) * _978) + (_1017 * ((((fma(_1378, _1374, half(2.0)) * pow(max(fma(half(-float(_1303)), _1303, half(1.0)), half(0.0)), half(0.5) * (_1378 * _1374))) * half(0.15915493667125701904296875)) * (_1291 * (_1378 * _1155))) * _983))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1236) * half(_1236)) / fast::max(_1222, 9.9999997473787516355514526367188e-05)) * half(_1255)) * half(_1255)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1413 = (fma(half4(_1036).xyz, _1017 * _976, (half3(float3(params.facet_diffuseColor)) * _917) * _978) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1059 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1061), half3(float3(0.0)), half3(float3(1.0)))) * _978) + (_1017 * ((((fma(_1148, _1144, half(2.0)) * pow(max(fma(half(-float(_1073)), _1073, half(1.0)), half(0.0)), half(0.5) * (_1148 * _1144))) * half(0.15915493667125701904296875)) * (_1061 * (_1148 * _1155))) * _983))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1336;
    float3 _1449 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1452 = dot(_1449, _1449);
    float3 _1457 = _1449 * rsqrt(fast::max(_1452, 9.9999999392252902907785028219223e-09));
    float _1461 = _1452 * float(frame.punctualLights[1].positionFalloff.w);
    float _1466 = fast::clamp(fma(-_1461, _1461, 1.0), 0.0, 1.0);
    float _1485 = fast::clamp(fma(dot(-_1457, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1519 = dot(_676, half3(_1457));
    half _1521 = clamp(_1519, half(0.0), half(1.0));
    half _1533 = clamp(dot(_676, half3(fast::normalize(_682 + _1457))), half(0.0), half(1.0));
    half _1604 = half(8192.0) * fma(half(-float(_1521)), _958, _1521 + _958);
    half _1608 = half(1.0) / (half(params.facet_alpha) * _1604);
    half3 _1566 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1519 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1521), half3(float3(0.0)), half3(float3(1.0)))) * _978) + (_1017 * ((((fma(_1608, _1604, half(2.0)) * pow(max(fma(half(-float(_1533)), _1533, half(1.0)), half(0.0)), half(0.5) * (_1608 * _1604))) * half(0.15915493667125701904296875)) * (_1521 * (_1608 * _1155))) * _983))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1466) * half(_1466)) / fast::max(_1452, 9.9999997473787516355514526367188e-05)) * half(_1485)) * half(_1485)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1413 + _1566, half(1.0)));
    return out;
}

