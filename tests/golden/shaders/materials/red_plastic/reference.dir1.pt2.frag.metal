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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _759 = fast::normalize(in.v_normal);
    float3 _765 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _920 = _759.y;
    float _925 = _759.z;
    float _930 = _759.x;
    float _1046 = fast::max(dot(_759, _765), 9.9999997473787516355514526367188e-05);
    float4 _1088 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1046, params.facet_perceptualRoughness), level(0.0));
    float3 _1107 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1088.y) - 1.0));
    float _1163 = fast::clamp(dot(_759, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1221 = fast::normalize(_765 + frame.lightDirection.xyz);
    float _1259 = 4096.0 * params.facet_alpha;
    float4 _1283 = float4(cross(_759, _1221), params.facet_alpha * fast::clamp(dot(_759, _1221), 0.0, 1.0)) * 64.0;
    float _1265 = _1259 / dot(_1283, _1283);
    float _1294 = params.facet_alpha * params.facet_alpha;
    float _1300 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1304 = sqrt(fma(_1046 * _1046, _1300, _1294));
    float _1327 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1221), 0.0, 1.0);
    float _1330 = _1327 * _1327;
    float3 _1338 = float3(1.0) - float3(params.facet_f0);
    float3 _1197 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1352 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _920)) + (frame.sh[2].xyz * _925)) + (frame.sh[3].xyz * _930)) + (((((frame.sh[4].xyz * (_930 * _920)) + (frame.sh[5].xyz * (_920 * _925))) + (frame.sh[6].xyz * fma(3.0 * _925, _925, -1.0))) + (frame.sh[7].xyz * (_930 * _925))) + (frame.sh[8].xyz * fma(_930, _930, -(_920 * _920)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_765, _759), level(params.facet_environmentLod)).xyz * (mix(_1088.xxx, _1088.yyy, float3(params.facet_f0)) * _1107)) + fast::min(fma((float3(params.facet_f0) + (_1338 * ((_1330 * _1330) * _1327))) * (((_1265 * _1265) * 0.3183098733425140380859375) * (0.5 / fma(_1163, _1304, _1046 * sqrt(fma(_1163 * _1163, _1300, _1294))))), _1107, _1197) * (frame.lightColor.xyz * _1163), float3(65504.0));
    float3 _1387 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1390 = dot(_1387, _1387);
    float3 _1395 = _1387 * rsqrt(fast::max(_1390, 9.9999999392252902907785028219223e-09));
    float _1399 = _1390 * float(frame.punctualLights[0].positionFalloff.w);
    float _1404 = fast::clamp(fma(-_1399, _1399, 1.0), 0.0, 1.0);
    float _1423 = fast::clamp(fma(dot(-_1395, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1480 = fast::clamp(dot(_759, _1395), 0.0, 1.0);
    float3 _1538 = fast::normalize(_765 + _1395);
    float4 _1600 = float4(cross(_759, _1538), params.facet_alpha * fast::clamp(dot(_759, _1538), 0.0, 1.0)) * 64.0;
    float _1582 = _1259 / dot(_1600, _1600);
    float _1644 = 1.0 - fast::clamp(dot(_1395, _1538), 0.0, 1.0);
    float _1647 = _1644 * _1644;
    float3 _1704 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1707 = dot(_1704, _1704);
    float3 _1712 = _1704 * rsqrt(fast::max(_1707, 9.9999999392252902907785028219223e-09));
    float _1716 = _1707 * float(frame.punctualLights[1].positionFalloff.w);
    float _1721 = fast::clamp(fma(-_1716, _1716, 1.0), 0.0, 1.0);
    float _1740 = fast::clamp(fma(dot(-_1712, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1797 = fast::clamp(dot(_759, _1712), 0.0, 1.0);
    float3 _1855 = fast::normalize(_765 + _1712);
    float4 _1917 = float4(cross(_759, _1855), params.facet_alpha * fast::clamp(dot(_759, _1855), 0.0, 1.0)) * 64.0;
    float _1899 = _1259 / dot(_1917, _1917);
    float _1961 = 1.0 - fast::clamp(dot(_1712, _1855), 0.0, 1.0);
    float _1964 = _1961 * _1961;
    float3 _1986 = (_1352 + fast::min(fma((float3(params.facet_f0) + (_1338 * ((_1647 * _1647) * _1644))) * (((_1582 * _1582) * 0.3183098733425140380859375) * (0.5 / fma(_1480, _1304, _1046 * sqrt(fma(_1480 * _1480, _1300, _1294))))), _1107, _1197) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1404 * _1404) / fast::max(_1390, 9.9999997473787516355514526367188e-05)) * _1423) * _1423)) * _1480), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1338 * ((_1964 * _1964) * _1961))) * (((_1899 * _1899) * 0.3183098733425140380859375) * (0.5 / fma(_1797, _1304, _1046 * sqrt(fma(_1797 * _1797, _1300, _1294))))), _1107, _1197) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1721 * _1721) / fast::max(_1707, 9.9999997473787516355514526367188e-05)) * _1740) * _1740)) * _1797), float3(65504.0));
    out.fragColor = float4(_1986, 1.0);
    return out;
}

