#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _958 = normalize(half3(in.v_normal));
    float3 _964 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1250 = max(dot(_958, half3(_964)), half(9.9999997473787516355514526367188e-05));
    half3 _1254 = reflect(-half3(_964), _958);
    float4 _1289 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1250, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1308 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1289).y) - half(1.0)));
    float4 _1315 = facet_environment.sample(facet_environmentSmplr, float3(_1254), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1363 = half(1.0) - _1250;
    half _1366 = _1363 * _1363;
    half _1373 = fma(half(0.959999978542327880859375), (_1366 * _1366) * _1363, half(0.039999999105930328369140625));
    half _1378 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1345 = fma(half(-float(_1373)), _1378, half(1.0));
    half _1383 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1390 = facet_environment.sample(facet_environmentSmplr, float3(_1254), level(_1383 * half(4.0)));
    float3 _1427 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1430 = dot(_1427, _1427);
    float3 _1435 = _1427 * rsqrt(fast::max(_1430, 9.9999999392252902907785028219223e-09));
    float _1439 = _1430 * float(frame.punctualLights[0].positionFalloff.w);
    float _1444 = fast::clamp(fma(-_1439, _1439, 1.0), 0.0, 1.0);
    float _1463 = fast::clamp(fma(dot(-_1435, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1599 = fast::normalize(_964 + _1435);
    half _1532 = clamp(dot(_958, half3(_1435)), half(0.0), half(1.0));
    half _1536 = clamp(dot(_958, half3(_1599)), half(0.0), half(1.0));
    half _1540 = clamp(dot(half3(_1435), half3(_1599)), half(0.0), half(1.0));
    half3 _1639 = cross(_958, half3(_1599));
    half _1642 = _1536 * half(params.facet_alpha);
    half _1646 = dot(_1639, _1639);
    half _1651 = half(params.facet_alpha) / fma(_1642, _1642, _1646);
    half _1665 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1671 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1675 = sqrt(fma(_1250 * _1250, _1671, _1665));
    half _1699 = half(1.0) - _1540;
    half _1702 = _1699 * _1699;
    half _1707 = (_1702 * _1702) * _1699;
    half3 _1710 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1558 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1444) * half(_1444)) / fast::max(_1430, 9.9999997473787516355514526367188e-05)) * half(_1463)) * half(_1463)), float3(65504.0))) * _1532;
    half _1744 = _1383 * _1383;
    half _1750 = _1536 * _1744;
    half _1761 = max(_1540 * _1540, half(6.103515625e-05));
    half _1764 = half(2048.0) * _1744;
    half _1769 = _1764 / (fma(_1750, _1750, _1646) * (_1761 * half(25735.927734375)));
    float3 _1868 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1871 = dot(_1868, _1868);
    float3 _1876 = _1868 * rsqrt(fast::max(_1871, 9.9999999392252902907785028219223e-09));
    float _1880 = _1871 * float(frame.punctualLights[1].positionFalloff.w);
    float _1885 = fast::clamp(fma(-_1880, _1880, 1.0), 0.0, 1.0);
    float _1904 = fast::clamp(fma(dot(-_1876, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2040 = fast::normalize(_964 + _1876);
    half _1973 = clamp(dot(_958, half3(_1876)), half(0.0), half(1.0));
    half _1977 = clamp(dot(_958, half3(_2040)), half(0.0), half(1.0));
    half _1981 = clamp(dot(half3(_1876), half3(_2040)), half(0.0), half(1.0));
    half3 _2080 = cross(_958, half3(_2040));
    half _2083 = _1977 * half(params.facet_alpha);
    half _2087 = dot(_2080, _2080);
    half _2092 = half(params.facet_alpha) / fma(_2083, _2083, _2087);
    half _2140 = half(1.0) - _1981;
    half _2143 = _2140 * _2140;
    half _2148 = (_2143 * _2143) * _2140;
    half3 _1999 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1885) * half(_1885)) / fast::max(_1871, 9.9999997473787516355514526367188e-05)) * half(_1904)) * half(_1904)), float3(65504.0))) * _1973;
    half _2191 = _1977 * _1744;
    half _2202 = max(_1981 * _1981, half(6.103515625e-05));
    half _2210 = _1764 / (fma(_2191, _2191, _2087) * (_2202 * half(25735.927734375)));
    half3 _2273 = (mix(half4(_1315).xyz * (mix(half4(_1289).xxx, half4(_1289).yyy, half3(float3(params.facet_f0))) * _1308), half4(_1390).xyz, half3(_1373 * _1378)) + min(fma(((half3(float3(params.facet_f0)) + (_1710 * _1707)) * min(min((_1651 * _1651) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1532, _1675, _1250 * sqrt(fma(_1532 * _1532, _1671, _1665))), half(65504.0)), half(65504.0))) * _1308, _1558 * _1345, _1558 * (min(_1769 * (_1769 * (half(12.56637096405029296875) * _1761)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1707, half(0.039999999105930328369140625)) * _1378))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1710 * _2148)) * min(min((_2092 * _2092) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1973, _1675, _1250 * sqrt(fma(_1973 * _1973, _1671, _1665))), half(65504.0)), half(65504.0))) * _1308, _1999 * _1345, _1999 * (min(_2210 * (_2210 * (half(12.56637096405029296875) * _2202)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2148, half(0.039999999105930328369140625)) * _1378))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2273, half(1.0)));
    return out;
}

