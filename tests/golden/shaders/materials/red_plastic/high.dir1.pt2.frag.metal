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
    half3 _783 = normalize(half3(in.v_normal));
    float3 _789 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _944 = _783.y;
    half _949 = _783.z;
    half _954 = _783.x;
    half3 _1022 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _944)) + (half4(frame.sh[2]).xyz * _949)) + (half4(frame.sh[3]).xyz * _954)) + (((((half4(frame.sh[4]).xyz * (_954 * _944)) + (half4(frame.sh[5]).xyz * (_944 * _949))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _949, _949, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_954 * _949))) + (half4(frame.sh[8]).xyz * fma(_954, _954, half(-float(_944 * _944))))), half3(float3(0.0)));
    half _1072 = max(dot(_783, half3(_789)), half(9.9999997473787516355514526367188e-05));
    float4 _1111 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1072, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1130 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1111).y) - half(1.0)));
    float4 _1137 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_789), _783)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1253 = fast::normalize(_789 + frame.lightDirection.xyz);
    half _1197 = clamp(dot(_783, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1294 = half(4096.0) * half(params.facet_alpha);
    half3 _1314 = cross(_783, half3(_1253)) * half(64.0);
    half _1317 = half(64.0) * half(params.facet_alpha);
    half _1318 = clamp(dot(_783, half3(_1253)), half(0.0), half(1.0)) * _1317;
    half _1300 = _1294 / fma(_1318, _1318, dot(_1314, _1314));
    half _1333 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1339 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1343 = sqrt(fma(_1072 * _1072, _1339, _1333));
    half _1367 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1253)), half(0.0), half(1.0));
    half _1370 = _1367 * _1367;
    half3 _1378 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1228 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1428 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1431 = dot(_1428, _1428);
    float3 _1436 = _1428 * rsqrt(fast::max(_1431, 9.9999999392252902907785028219223e-09));
    float _1440 = _1431 * float(frame.punctualLights[0].positionFalloff.w);
    float _1445 = fast::clamp(fma(-_1440, _1440, 1.0), 0.0, 1.0);
    float _1464 = fast::clamp(fma(dot(-_1436, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1583 = fast::normalize(_789 + _1436);
    half _1527 = clamp(dot(_783, half3(_1436)), half(0.0), half(1.0));
    half3 _1644 = cross(_783, half3(_1583)) * half(64.0);
    half _1648 = clamp(dot(_783, half3(_1583)), half(0.0), half(1.0)) * _1317;
    half _1630 = _1294 / fma(_1648, _1648, dot(_1644, _1644));
    half _1697 = half(1.0) - clamp(dot(half3(_1436), half3(_1583)), half(0.0), half(1.0));
    half _1700 = _1697 * _1697;
    half3 _1722 = (fma(half3(float3(params.facet_diffuseColor)), _1022, half4(_1137).xyz * (mix(half4(_1111).xxx, half4(_1111).yyy, half3(float3(params.facet_f0))) * _1130)) + min(fma((half3(float3(params.facet_f0)) + (_1378 * ((_1370 * _1370) * _1367))) * min(min((_1300 * _1300) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1197, _1343, _1072 * sqrt(fma(_1197 * _1197, _1339, _1333))), half(65504.0)), half(65504.0)), _1130, _1228) * (half4(frame.lightColor).xyz * _1197), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1378 * ((_1700 * _1700) * _1697))) * min(min((_1630 * _1630) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1527, _1343, _1072 * sqrt(fma(_1527 * _1527, _1339, _1333))), half(65504.0)), half(65504.0)), _1130, _1228) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1445) * half(_1445)) / fast::max(_1431, 9.9999997473787516355514526367188e-05)) * half(_1464)) * half(_1464)), float3(65504.0))) * _1527), half3(float3(65504.0)));
    float3 _1758 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1761 = dot(_1758, _1758);
    float3 _1766 = _1758 * rsqrt(fast::max(_1761, 9.9999999392252902907785028219223e-09));
    float _1770 = _1761 * float(frame.punctualLights[1].positionFalloff.w);
    float _1775 = fast::clamp(fma(-_1770, _1770, 1.0), 0.0, 1.0);
    float _1794 = fast::clamp(fma(dot(-_1766, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1913 = fast::normalize(_789 + _1766);
    half _1857 = clamp(dot(_783, half3(_1766)), half(0.0), half(1.0));
    half3 _1974 = cross(_783, half3(_1913)) * half(64.0);
    half _1978 = clamp(dot(_783, half3(_1913)), half(0.0), half(1.0)) * _1317;
    half _1960 = _1294 / fma(_1978, _1978, dot(_1974, _1974));
    half _2027 = half(1.0) - clamp(dot(half3(_1766), half3(_1913)), half(0.0), half(1.0));
    half _2030 = _2027 * _2027;
    half3 _2052 = _1722 + min(fma((half3(float3(params.facet_f0)) + (_1378 * ((_2030 * _2030) * _2027))) * min(min((_1960 * _1960) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1857, _1343, _1072 * sqrt(fma(_1857 * _1857, _1339, _1333))), half(65504.0)), half(65504.0)), _1130, _1228) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1775) * half(_1775)) / fast::max(_1761, 9.9999997473787516355514526367188e-05)) * half(_1794)) * half(_1794)), float3(65504.0))) * _1857), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2052, half(1.0)));
    return out;
}

