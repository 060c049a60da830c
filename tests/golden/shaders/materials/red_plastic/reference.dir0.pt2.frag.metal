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
    float3 _752 = fast::normalize(in.v_normal);
    float3 _758 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _892 = _752.y;
    float _897 = _752.z;
    float _902 = _752.x;
    float _1020 = fast::max(dot(_752, _758), 9.9999997473787516355514526367188e-05);
    float4 _1059 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1020, params.facet_perceptualRoughness), level(0.0));
    float3 _1078 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1059.y) - 1.0));
    float3 _1129 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1132 = dot(_1129, _1129);
    float3 _1137 = _1129 * rsqrt(fast::max(_1132, 9.9999999392252902907785028219223e-09));
    float _1141 = _1132 * float(frame.punctualLights[0].positionFalloff.w);
    float _1146 = fast::clamp(fma(-_1141, _1141, 1.0), 0.0, 1.0);
    float _1165 = fast::clamp(fma(dot(-_1137, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1280 = fast::normalize(_758 + _1137);
    float _1225 = fast::clamp(dot(_752, _1137), 0.0, 1.0);
    float3 _1318 = cross(_752, _1280);
    float _1321 = fast::clamp(dot(_752, _1280), 0.0, 1.0) * params.facet_alpha;
    float _1330 = params.facet_alpha / fma(_1321, _1321, dot(_1318, _1318));
    float _1343 = params.facet_alpha * params.facet_alpha;
    float _1349 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1353 = sqrt(fma(_1020 * _1020, _1349, _1343));
    float _1376 = 1.0 - fast::clamp(dot(_1137, _1280), 0.0, 1.0);
    float _1379 = _1376 * _1376;
    float3 _1387 = float3(1.0) - float3(params.facet_f0);
    float3 _1256 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1401 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _892)) + (frame.sh[2].xyz * _897)) + (frame.sh[3].xyz * _902)) + (((((frame.sh[4].xyz * (_902 * _892)) + (frame.sh[5].xyz * (_892 * _897))) + (frame.sh[6].xyz * fma(3.0 * _897, _897, -1.0))) + (frame.sh[7].xyz * (_902 * _897))) + (frame.sh[8].xyz * fma(_902, _902, -(_892 * _892)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_758, _752), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1059.xxx, _1059.yyy, float3(params.facet_f0)) * _1078)) + fast::min(fma((float3(params.facet_f0) + (_1387 * ((_1379 * _1379) * _1376))) * (((_1330 * _1330) * 0.3183098733425140380859375) * (0.5 / fma(_1225, _1353, _1020 * sqrt(fma(_1225 * _1225, _1349, _1343))))), _1078, _1256) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1146 * _1146) / fast::max(_1132, 9.9999997473787516355514526367188e-05)) * _1165) * _1165)) * _1225), float3(65504.0));
    float3 _1436 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1439 = dot(_1436, _1436);
    float3 _1444 = _1436 * rsqrt(fast::max(_1439, 9.9999999392252902907785028219223e-09));
    float _1448 = _1439 * float(frame.punctualLights[1].positionFalloff.w);
    float _1453 = fast::clamp(fma(-_1448, _1448, 1.0), 0.0, 1.0);
    float _1472 = fast::clamp(fma(dot(-_1444, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1587 = fast::normalize(_758 + _1444);
    float _1532 = fast::clamp(dot(_752, _1444), 0.0, 1.0);
    float3 _1625 = cross(_752, _1587);
    float _1628 = fast::clamp(dot(_752, _1587), 0.0, 1.0) * params.facet_alpha;
    float _1637 = params.facet_alpha / fma(_1628, _1628, dot(_1625, _1625));
    float _1683 = 1.0 - fast::clamp(dot(_1444, _1587), 0.0, 1.0);
    float _1686 = _1683 * _1683;
    out.fragColor = float4(_1401 + fast::min(fma((float3(params.facet_f0) + (_1387 * ((_1686 * _1686) * _1683))) * (((_1637 * _1637) * 0.3183098733425140380859375) * (0.5 / fma(_1532, _1353, _1020 * sqrt(fma(_1532 * _1532, _1349, _1343))))), _1078, _1256) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1453 * _1453) / fast::max(_1439, 9.9999997473787516355514526367188e-05)) * _1472) * _1472)) * _1532), float3(65504.0)), 1.0);
    return out;
}

