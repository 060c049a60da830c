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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    float3 _651 = fast::normalize(in.v_normal);
    float3 _657 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _814 = _651.y;
    float _819 = _651.z;
    float _824 = _651.x;
    float _931 = fast::max(dot(_651, _657), 9.9999997473787516355514526367188e-05);
    float4 _936 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_931, params.facet_perceptualRoughness), level(0.0));
    float _949 = _936.z;
    float _951 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _949, 1.0);
    float _956 = _936.w;
    float _1021 = dot(_651, frame.lightDirection.xyz);
    float _1023 = fast::clamp(_1021, 0.0, 1.0);
    float _1035 = fast::clamp(dot(_651, fast::normalize(_657 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1104 = 8192.0 * fma(-_1023, _931, _1023 + _931);
    float _1108 = 1.0 / (params.facet_alpha * _1104);
    float _1115 = 2048.0 * params.facet_alpha;
    float3 _1143 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_657, _651), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _949, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _814)) + (frame.sh[2].xyz * _819)) + (frame.sh[3].xyz * _824)) + (((((frame.sh[4].xyz * (_824 * _814)) + (frame.sh[5].xyz * (_814 * _819))) + (frame.sh[6].xyz * fma(3.0 * _819, _819, -1.0))) + (frame.sh[7].xyz * (_824 * _819))) + (frame.sh[8].xyz * fma(_824, _824, -(_814 * _814)))), float3(0.0))) * _951) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1021 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1023), float3(0.0), float3(1.0))) * _951) + (float3(params.facet_sheenColor) * ((((fma(_1108, _1104, 2.0) * pow(fast::max(fma(-_1035, _1035, 1.0), 0.0), 0.5 * (_1108 * _1104))) * 0.15915493667125701904296875) * (_1023 * (_1108 * _1115))) * _956))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1178 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1181 = dot(_1178, _1178);
    float3 _1186 = _1178 * rsqrt(fast::max(_1181, 9.9999999392252902907785028219223e-09));
    float _1190 = _1181 * float(frame.punctualLights[0].positionFalloff.w);
    float _1195 = fast::clamp(fma(-_1190, _1190, 1.0), 0.0, 1.0);
    float _1214 = fast::clamp(fma(dot(-_1186, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1245 = dot(_651, _1186);
    float _1247 = fast::clamp(_1245, 0.0, 1.0);
    float _1259 = fast::clamp(dot(_651, fast::normalize(_657 + _1186)), 0.0, 1.0);
    float _1328 = 8192.0 * fma(-_1247, _931, _1247 + _931);
    float _1332 = 1.0 / (params.facet_alpha * _1328);
    float3 _1402 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1405 = dot(_1402, _1402);
    float3 _1410 = _1402 * rsqrt(fast::max(_1405, 9.9999999392252902907785028219223e-09));
    float _1414 = _1405 * float(frame.punctualLights[1].positionFalloff.w);
    float _1419 = fast::clamp(fma(-_1414, _1414, 1.0), 0.0, 1.0);
    float _1438 = fast::clamp(fma(dot(-_1410, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1469 = dot(_651, _1410);
    float _1471 = fast::clamp(_1469, 0.0, 1.0);
    float _1483 = fast::clamp(dot(_651, fast::normalize(_657 + _1410)), 0.0, 1.0);
    float _1552 = 8192.0 * fma(-_1471, _931, _1471 + _931);
    float _1556 = 1.0 / (params.facet_alpha * _1552);
    float3 _1591 = (_1143 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1245 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1247), float3(0.0), float3(1.0))) * _951) + (float3(params.facet_sheenColor) * ((((fma(_1332, _1328, 2.0) * pow(fast::max(fma(-_1259, _1259, 1.0), 0.0), 0.5 * (_1332 * _1328))) * 0.15915493667125701904296875) * (_1247 * (_1332 * _1115))) * _956))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1195 * _1195) / fast::max(_1181, 9.9999997473787516355514526367188e-05)) * _1214) * _1214)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1469 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1471), float3(0.0), float3(1.0))) * _951) + (float3(params.facet_sheenColor) * ((((fma(_1556, _1552, 2.0) * pow(fast::max(fma(-_1483, _1483, 1.0), 0.0), 0.5 * (_1556 * _1552))) * 0.15915493667125701904296875) * (_1471 * (_1556 * _1115))) * _956))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1419 * _1419) / fast::max(_1405, 9.9999997473787516355514526367188e-05)) * _1438) * _1438)), float3(65504.0));
    out.fragColor = float4(_1591, 1.0);
    return out;
}

