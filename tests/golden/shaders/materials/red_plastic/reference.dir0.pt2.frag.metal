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
    float3 _756 = fast::normalize(in.v_normal);
    float3 _762 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _896 = _756.y;
    float _901 = _756.z;
    float _906 = _756.x;
    float _1024 = fast::max(dot(_756, _762), 9.9999997473787516355514526367188e-05);
    float4 _1063 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1024, params.facet_perceptualRoughness), level(0.0));
    float3 _1082 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1063.y) - 1.0));
    float3 _1136 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1139 = dot(_1136, _1136);
    float3 _1144 = _1136 * rsqrt(fast::max(_1139, 9.9999999392252902907785028219223e-09));
    float _1148 = _1139 * float(frame.punctualLights[0].positionFalloff.w);
    float _1153 = fast::clamp(fma(-_1148, _1148, 1.0), 0.0, 1.0);
    float _1172 = fast::clamp(fma(dot(-_1144, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1287 = fast::normalize(_762 + _1144);
    float _1232 = fast::clamp(dot(_756, _1144), 0.0, 1.0);
    float3 _1325 = cross(_756, _1287);
    float _1328 = fast::clamp(dot(_756, _1287), 0.0, 1.0) * params.facet_alpha;
    float _1337 = params.facet_alpha / fma(_1328, _1328, dot(_1325, _1325));
    float _1350 = params.facet_alpha * params.facet_alpha;
    float _1356 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1360 = sqrt(fma(_1024 * _1024, _1356, _1350));
    float _1383 = 1.0 - fast::clamp(dot(_1144, _1287), 0.0, 1.0);
    float _1386 = _1383 * _1383;
    float3 _1394 = float3(1.0) - float3(params.facet_f0);
    float3 _1263 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1408 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _896)) + (frame.sh[2].xyz * _901)) + (frame.sh[3].xyz * _906)) + (((((frame.sh[4].xyz * (_906 * _896)) + (frame.sh[5].xyz * (_896 * _901))) + (frame.sh[6].xyz * fma(3.0 * _901, _901, -1.0))) + (frame.sh[7].xyz * (_906 * _901))) + (frame.sh[8].xyz * fma(_906, _906, -(_896 * _896)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_762, _756), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1063.xxx, _1063.yyy, float3(params.facet_f0)) * _1082)) + fast::min(fma((float3(params.facet_f0) + (_1394 * ((_1386 * _1386) * _1383))) * (((_1337 * _1337) * 0.3183098733425140380859375) * (0.5 / fma(_1232, _1360, _1024 * sqrt(fma(_1232 * _1232, _1356, _1350))))), _1082, _1263) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1153 * _1153) / fast::max(_1139, 9.9999997473787516355514526367188e-05)) * _1172) * _1172)) * _1232), float3(65504.0));
    float3 _1443 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1446 = dot(_1443, _1443);
    float3 _1451 = _1443 * rsqrt(fast::max(_1446, 9.9999999392252902907785028219223e-09));
    float _1455 = _1446 * float(frame.punctualLights[1].positionFalloff.w);
    float _1460 = fast::clamp(fma(-_1455, _1455, 1.0), 0.0, 1.0);
    float _1479 = fast::clamp(fma(dot(-_1451, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1594 = fast::normalize(_762 + _1451);
    float _1539 = fast::clamp(dot(_756, _1451), 0.0, 1.0);
    float3 _1632 = cross(_756, _1594);
    float _1635 = fast::clamp(dot(_756, _1594), 0.0, 1.0) * params.facet_alpha;
    float _1644 = params.facet_alpha / fma(_1635, _1635, dot(_1632, _1632));
    float _1690 = 1.0 - fast::clamp(dot(_1451, _1594), 0.0, 1.0);
    float _1693 = _1690 * _1690;
    out.fragColor = float4(_1408 + fast::min(fma((float3(params.facet_f0) + (_1394 * ((_1693 * _1693) * _1690))) * (((_1644 * _1644) * 0.3183098733425140380859375) * (0.5 / fma(_1539, _1360, _1024 * sqrt(fma(_1539 * _1539, _1356, _1350))))), _1082, _1263) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1460 * _1460) / fast::max(_1446, 9.9999997473787516355514526367188e-05)) * _1479) * _1479)) * _1539), float3(65504.0)), 1.0);
    return out;
}

