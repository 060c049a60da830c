#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _761 = normalize(half3(in.v_normal));
    float3 _767 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _925 = _761.y;
    half _930 = _761.z;
    half _935 = _761.x;
    half3 _1003 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _925)) + (half4(frame.sh[2]).xyz * _930)) + (half4(frame.sh[3]).xyz * _935)) + (((((half4(frame.sh[4]).xyz * (_935 * _925)) + (half4(frame.sh[5]).xyz * (_925 * _930))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _930, _930, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_935 * _930))) + (half4(frame.sh[8]).xyz * fma(_935, _935, half(-float(_925 * _925))))), half3(float3(0.0)));
    half _1053 = max(dot(_761, half3(_767)), half(9.9999997473787516355514526367188e-05));
    float4 _1092 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1053, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1111 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1092).y) - half(1.0)));
    float4 _1118 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_767), _761)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1234 = fast::normalize(_767 + frame.lightDirection.xyz);
    half _1178 = clamp(dot(_761, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1274 = cross(_761, half3(_1234));
    half _1277 = clamp(dot(_761, half3(_1234)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1286 = half(params.facet_alpha) / fma(_1277, _1277, dot(_1274, _1274));
    half _1300 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1306 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1310 = sqrt(fma(_1053 * _1053, _1306, _1300));
    half _1334 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1234)), half(0.0), half(1.0));
    half _1337 = _1334 * _1334;
    half3 _1345 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1209 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1395 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1398 = dot(_1395, _1395);
    float3 _1403 = _1395 * rsqrt(fast::max(_1398, 9.9999999392252902907785028219223e-09));
    float _1407 = _1398 * float(frame.punctualLights[0].positionFalloff.w);
    float _1412 = fast::clamp(fma(-_1407, _1407, 1.0), 0.0, 1.0);
    float _1431 = fast::clamp(fma(dot(-_1403, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1550 = fast::normalize(_767 + _1403);
    half _1494 = clamp(dot(_761, half3(_1403)), half(0.0), half(1.0));
    half3 _1590 = cross(_761, half3(_1550));
    half _1593 = clamp(dot(_761, half3(_1550)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1602 = half(params.facet_alpha) / fma(_1593, _1593, dot(_1590, _1590));
    half _1650 = half(1.0) - clamp(dot(half3(_1403), half3(_1550)), half(0.0), half(1.0));
    half _1653 = _1650 * _1650;
    half3 _1675 = (fma(half3(float3(params.facet_diffuseColor)), _1003, half4(_1118).xyz * (mix(half4(_1092).xxx, half4(_1092).yyy, half3(float3(params.facet_f0))) * _1111)) + min(fma((half3(float3(params.facet_f0)) + (_1345 * ((_1337 * _1337) * _1334))) * min(min((_1286 * _1286) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1178, _1310, _1053 * sqrt(fma(_1178 * _1178, _1306, _1300))), half(65504.0)), half(65504.0)), _1111, _1209) * (half4(frame.lightColor).xyz * _1178), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1345 * ((_1653 * _1653) * _1650))) * min(min((_1602 * _1602) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1494, _1310, _1053 * sqrt(fma(_1494 * _1494, _1306, _1300))), half(65504.0)), half(65504.0)), _1111, _1209) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1412) * half(_1412)) / fast::max(_1398, 9.9999997473787516355514526367188e-05)) * half(_1431)) * half(_1431)), float3(65504.0))) * _1494), half3(float3(65504.0)));
    float3 _1711 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1714 = dot(_1711, _1711);
    float3 _1719 = _1711 * rsqrt(fast::max(_1714, 9.9999999392252902907785028219223e-09));
    float _1723 = _1714 * float(frame.punctualLights[1].positionFalloff.w);
    float _1728 = fast::clamp(fma(-_1723, _1723, 1.0), 0.0, 1.0);
    float _1747 = fast::clamp(fma(dot(-_1719, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1866 = fast::normalize(_767 + _1719);
    half _1810 = clamp(dot(_761, half3(_1719)), half(0.0), half(1.0));
    half3 _1906 = cross(_761, half3(_1866));
    half _1909 = clamp(dot(_761, half3(_1866)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1918 = half(params.facet_alpha) / fma(_1909, _1909, dot(_1906, _1906));
    half _1966 = half(1.0) - clamp(dot(half3(_1719), half3(_1866)), half(0.0), half(1.0));
    half _1969 = _1966 * _1966;
    half3 _1991 = _1675 + min(fma((half3(float3(params.facet_f0)) + (_1345 * ((_1969 * _1969) * _1966))) * min(min((_1918 * _1918) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1810, _1310, _1053 * sqrt(fma(_1810 * _1810, _1306, _1300))), half(65504.0)), half(65504.0)), _1111, _1209) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1728) * half(_1728)) / fast::max(_1714, 9.9999997473787516355514526367188e-05)) * half(_1747)) * half(_1747)), float3(65504.0))) * _1810), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1991, half(1.0)));
    return out;
}

