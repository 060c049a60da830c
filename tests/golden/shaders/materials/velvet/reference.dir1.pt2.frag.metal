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
    float3 _667 = fast::normalize(in.v_normal);
    float3 _673 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _832 = _667.y;
    float _837 = _667.z;
    float _842 = _667.x;
    float _951 = fast::max(dot(_667, _673), 9.9999997473787516355514526367188e-05);
    float4 _956 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_951, params.facet_perceptualRoughness), level(0.0));
    float3 _1010 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _969 = _956.z;
    float _971 = fma(-fast::max(_1010.x, fast::max(_1010.y, _1010.z)), _969, 1.0);
    float _976 = _956.w;
    float _1049 = dot(_667, frame.lightDirection.xyz);
    float _1051 = fast::clamp(_1049, 0.0, 1.0);
    float _1063 = fast::clamp(dot(_667, fast::normalize(_673 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1132 = 8192.0 * fma(-_1051, _951, _1051 + _951);
    float _1136 = 1.0 / (params.facet_alpha * _1132);
    float _1143 = 2048.0 * params.facet_alpha;
    float3 _1171 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_673, _667), level(params.facet_perceptualRoughness * 4.0)).xyz, _1010 * _969, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _832)) + (frame.sh[2].xyz * _837)) + (frame.sh[3].xyz * _842)) + (((((frame.sh[4].xyz * (_842 * _832)) + (frame.sh[5].xyz * (_832 * _837))) + (frame.sh[6].xyz * fma(3.0 * _837, _837, -1.0))) + (frame.sh[7].xyz * (_842 * _837))) + (frame.sh[8].xyz * fma(_842, _842, -(_832 * _832)))), float3(0.0))) * _971) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1049 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1051), float3(0.0), float3(1.0))) * _971) + (_1010 * ((((fma(_1136, _1132, 2.0) * pow(fast::max(fma(-_1063, _1063, 1.0), 0.0), 0.5 * (_1136 * _1132))) * 0.15915493667125701904296875) * (_1051 * (_1136 * _1143))) * _976))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1206 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1209 = dot(_1206, _1206);
    float3 _1214 = _1206 * rsqrt(fast::max(_1209, 9.9999999392252902907785028219223e-09));
    float _1218 = _1209 * float(frame.punctualLights[0].positionFalloff.w);
    float _1223 = fast::clamp(fma(-_1218, _1218, 1.0), 0.0, 1.0);
    float _1242 = fast::clamp(fma(dot(-_1214, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1273 = dot(_667, _1214);
    float _1275 = fast::clamp(_1273, 0.0, 1.0);
    float _1287 = fast::clamp(dot(_667, fast::normalize(_673 + _1214)), 0.0, 1.0);
    float _1356 = 8192.0 * fma(-_1275, _951, _1275 + _951);
    float _1360 = 1.0 / (params.facet_alpha * _1356);
    float3 _1430 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1433 = dot(_1430, _1430);
    float3 _1438 = _1430 * rsqrt(fast::max(_1433, 9.9999999392252902907785028219223e-09));
    float _1442 = _1433 * float(frame.punctualLights[1].positionFalloff.w);
    float _1447 = fast::clamp(fma(-_1442, _1442, 1.0), 0.0, 1.0);
    float _1466 = fast::clamp(fma(dot(-_1438, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1497 = dot(_667, _1438);
    float _1499 = fast::clamp(_1497, 0.0, 1.0);
    float _1511 = fast::clamp(dot(_667, fast::normalize(_673 + _1438)), 0.0, 1.0);
    float _1580 = 8192.0 * fma(-_1499, _951, _1499 + _951);
    float _1584 = 1.0 / (params.facet_alpha * _1580);
    float3 _1619 = (_1171 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1273 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1275), float3(0.0), float3(1.0))) * _971) + (_1010 * ((((fma(_1360, _1356, 2.0) * pow(fast::max(fma(-_1287, _1287, 1.0), 0.0), 0.5 * (_1360 * _1356))) * 0.15915493667125701904296875) * (_1275 * (_1360 * _1143))) * _976))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1223 * _1223) / fast::max(_1209, 9.9999997473787516355514526367188e-05)) * _1242) * _1242)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1497 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1499), float3(0.0), float3(1.0))) * _971) + (_1010 * ((((fma(_1584, _1580, 2.0) * pow(fast::max(fma(-_1511, _1511, 1.0), 0.0), 0.5 * (_1584 * _1580))) * 0.15915493667125701904296875) * (_1499 * (_1584 * _1143))) * _976))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1447 * _1447) / fast::max(_1433, 9.9999997473787516355514526367188e-05)) * _1466) * _1466)), float3(65504.0));
    out.fragColor = float4(_1619, 1.0);
    return out;
}

