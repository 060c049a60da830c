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
    float _895 = _752.y;
    float _900 = _752.z;
    float _905 = _752.x;
    float _1023 = fast::max(dot(_752, _758), 9.9999997473787516355514526367188e-05);
    float4 _1062 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1023, params.facet_perceptualRoughness), level(0.0));
    float3 _1081 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1062.y) - 1.0));
    float3 _1132 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1135 = dot(_1132, _1132);
    float3 _1140 = _1132 * rsqrt(fast::max(_1135, 9.9999999392252902907785028219223e-09));
    float _1144 = _1135 * float(frame.punctualLights[0].positionFalloff.w);
    float _1149 = fast::clamp(fma(-_1144, _1144, 1.0), 0.0, 1.0);
    float _1168 = fast::clamp(fma(dot(-_1140, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1283 = fast::normalize(_758 + _1140);
    float _1228 = fast::clamp(dot(_752, _1140), 0.0, 1.0);
    float3 _1321 = cross(_752, _1283);
    float _1324 = fast::clamp(dot(_752, _1283), 0.0, 1.0) * params.facet_alpha;
    float _1333 = params.facet_alpha / fma(_1324, _1324, dot(_1321, _1321));
    float _1346 = params.facet_alpha * params.facet_alpha;
    float _1352 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1356 = sqrt(fma(_1023 * _1023, _1352, _1346));
    float _1379 = 1.0 - fast::clamp(dot(_1140, _1283), 0.0, 1.0);
    float _1382 = _1379 * _1379;
    float3 _1390 = float3(1.0) - float3(params.facet_f0);
    float3 _1259 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1404 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _895)) + (frame.sh[2].xyz * _900)) + (frame.sh[3].xyz * _905)) + (((((frame.sh[4].xyz * (_905 * _895)) + (frame.sh[5].xyz * (_895 * _900))) + (frame.sh[6].xyz * fma(3.0 * _900, _900, -1.0))) + (frame.sh[7].xyz * (_905 * _900))) + (frame.sh[8].xyz * fma(_905, _905, -(_895 * _895)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_758, _752), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1062.xxx, _1062.yyy, float3(params.facet_f0)) * _1081)) + fast::min(fma((float3(params.facet_f0) + (_1390 * ((_1382 * _1382) * _1379))) * (((_1333 * _1333) * 0.3183098733425140380859375) * (0.5 / fma(_1228, _1356, _1023 * sqrt(fma(_1228 * _1228, _1352, _1346))))), _1081, _1259) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1149 * _1149) / fast::max(_1135, 9.9999997473787516355514526367188e-05)) * _1168) * _1168)) * _1228), float3(65504.0));
    float3 _1439 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1442 = dot(_1439, _1439);
    float3 _1447 = _1439 * rsqrt(fast::max(_1442, 9.9999999392252902907785028219223e-09));
    float _1451 = _1442 * float(frame.punctualLights[1].positionFalloff.w);
    float _1456 = fast::clamp(fma(-_1451, _1451, 1.0), 0.0, 1.0);
    float _1475 = fast::clamp(fma(dot(-_1447, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1590 = fast::normalize(_758 + _1447);
    float _1535 = fast::clamp(dot(_752, _1447), 0.0, 1.0);
    float3 _1628 = cross(_752, _1590);
    float _1631 = fast::clamp(dot(_752, _1590), 0.0, 1.0) * params.facet_alpha;
    float _1640 = params.facet_alpha / fma(_1631, _1631, dot(_1628, _1628));
    float _1686 = 1.0 - fast::clamp(dot(_1447, _1590), 0.0, 1.0);
    float _1689 = _1686 * _1686;
    out.fragColor = float4(_1404 + fast::min(fma((float3(params.facet_f0) + (_1390 * ((_1689 * _1689) * _1686))) * (((_1640 * _1640) * 0.3183098733425140380859375) * (0.5 / fma(_1535, _1356, _1023 * sqrt(fma(_1535 * _1535, _1352, _1346))))), _1081, _1259) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1456 * _1456) / fast::max(_1442, 9.9999997473787516355514526367188e-05)) * _1475) * _1475)) * _1535), float3(65504.0)), 1.0);
    return out;
}

