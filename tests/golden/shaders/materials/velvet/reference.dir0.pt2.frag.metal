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
    float _793 = _651.y;
    float _798 = _651.z;
    float _803 = _651.x;
    float _910 = fast::max(dot(_651, _657), 9.9999997473787516355514526367188e-05);
    float4 _915 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_910, params.facet_perceptualRoughness), level(0.0));
    float _928 = _915.z;
    float _930 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _928, 1.0);
    float _935 = _915.w;
    float3 _1013 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1016 = dot(_1013, _1013);
    float3 _1021 = _1013 * rsqrt(fast::max(_1016, 9.9999999392252902907785028219223e-09));
    float _1025 = _1016 * float(frame.punctualLights[0].positionFalloff.w);
    float _1030 = fast::clamp(fma(-_1025, _1025, 1.0), 0.0, 1.0);
    float _1049 = fast::clamp(fma(dot(-_1021, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1080 = dot(_651, _1021);
    float _1082 = fast::clamp(_1080, 0.0, 1.0);
    float _1094 = fast::clamp(dot(_651, fast::normalize(_657 + _1021)), 0.0, 1.0);
    float _1163 = 8192.0 * fma(-_1082, _910, _1082 + _910);
    float _1167 = 1.0 / (params.facet_alpha * _1163);
    float _1174 = 2048.0 * params.facet_alpha;
    float3 _1202 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_657, _651), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _928, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _793)) + (frame.sh[2].xyz * _798)) + (frame.sh[3].xyz * _803)) + (((((frame.sh[4].xyz * (_803 * _793)) + (frame.sh[5].xyz * (_793 * _798))) + (frame.sh[6].xyz * fma(3.0 * _798, _798, -1.0))) + (frame.sh[7].xyz * (_803 * _798))) + (frame.sh[8].xyz * fma(_803, _803, -(_793 * _793)))), float3(0.0))) * _930) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1080 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1082), float3(0.0), float3(1.0))) * _930) + (float3(params.facet_sheenColor) * ((((fma(_1167, _1163, 2.0) * pow(fast::max(fma(-_1094, _1094, 1.0), 0.0), 0.5 * (_1167 * _1163))) * 0.15915493667125701904296875) * (_1082 * (_1167 * _1174))) * _935))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1030 * _1030) / fast::max(_1016, 9.9999997473787516355514526367188e-05)) * _1049) * _1049)), float3(65504.0));
    float3 _1237 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1240 = dot(_1237, _1237);
    float3 _1245 = _1237 * rsqrt(fast::max(_1240, 9.9999999392252902907785028219223e-09));
    float _1249 = _1240 * float(frame.punctualLights[1].positionFalloff.w);
    float _1254 = fast::clamp(fma(-_1249, _1249, 1.0), 0.0, 1.0);
    float _1273 = fast::clamp(fma(dot(-_1245, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1304 = dot(_651, _1245);
    float _1306 = fast::clamp(_1304, 0.0, 1.0);
    float _1318 = fast::clamp(dot(_651, fast::normalize(_657 + _1245)), 0.0, 1.0);
    float _1387 = 8192.0 * fma(-_1306, _910, _1306 + _910);
    float _1391 = 1.0 / (params.facet_alpha * _1387);
    out.fragColor = float4(_1202 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1304 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1306), float3(0.0), float3(1.0))) * _930) + (float3(params.facet_sheenColor) * ((((fma(_1391, _1387, 2.0) * pow(fast::max(fma(-_1318, _1318, 1.0), 0.0), 0.5 * (_1391 * _1387))) * 0.15915493667125701904296875) * (_1306 * (_1391 * _1174))) * _935))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1254 * _1254) / fast::max(_1240, 9.9999997473787516355514526367188e-05)) * _1273) * _1273)), float3(65504.0)), 1.0);
    return out;
}

