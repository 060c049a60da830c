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
    float3 _670 = fast::normalize(in.v_normal);
    float3 _676 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _812 = _670.y;
    float _817 = _670.z;
    float _822 = _670.x;
    float _931 = fast::max(dot(_670, _676), 9.9999997473787516355514526367188e-05);
    float4 _936 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_931, params.facet_perceptualRoughness), level(0.0));
    float3 _990 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _949 = _936.z;
    float _951 = fma(-fast::max(_990.x, fast::max(_990.y, _990.z)), _949, 1.0);
    float _956 = _936.w;
    float3 _1045 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1048 = dot(_1045, _1045);
    float3 _1053 = _1045 * rsqrt(fast::max(_1048, 9.9999999392252902907785028219223e-09));
    float _1057 = _1048 * float(frame.punctualLights[0].positionFalloff.w);
    float _1062 = fast::clamp(fma(-_1057, _1057, 1.0), 0.0, 1.0);
    float _1081 = fast::clamp(fma(dot(-_1053, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1112 = dot(_670, _1053);
    float _1114 = fast::clamp(_1112, 0.0, 1.0);
    float _1126 = fast::clamp(dot(_670, fast::normalize(_676 + _1053)), 0.0, 1.0);
    float _1195 = 8192.0 * fma(-_1114, _931, _1114 + _931);
    float _1199 = 1.0 / (params.facet_alpha * _1195);
    float _1206 = 2048.0 * params.facet_alpha;
    float3 _1234 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_676, _670), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _990 * _949, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _812)) + (frame.sh[2].xyz * _817)) + (frame.sh[3].xyz * _822)) + (((((frame.sh[4].xyz * (_822 * _812)) + (frame.sh[5].xyz * (_812 * _817))) + (frame.sh[6].xyz * fma(3.0 * _817, _817, -1.0))) + (frame.sh[7].xyz * (_822 * _817))) + (frame.sh[8].xyz * fma(_822, _822, -(_812 * _812)))), float3(0.0))) * _951) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1112 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1114), float3(0.0), float3(1.0))) * _951) + (_990 * ((((fma(_1199, _1195, 2.0) * pow(fast::max(fma(-_1126, _1126, 1.0), 0.0), 0.5 * (_1199 * _1195))) * 0.15915493667125701904296875) * (_1114 * (_1199 * _1206))) * _956))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1062 * _1062) / fast::max(_1048, 9.9999997473787516355514526367188e-05)) * _1081) * _1081)), float3(65504.0));
    float3 _1269 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1272 = dot(_1269, _1269);
    float3 _1277 = _1269 * rsqrt(fast::max(_1272, 9.9999999392252902907785028219223e-09));
    float _1281 = _1272 * float(frame.punctualLights[1].positionFalloff.w);
    float _1286 = fast::clamp(fma(-_1281, _1281, 1.0), 0.0, 1.0);
    float _1305 = fast::clamp(fma(dot(-_1277, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1336 = dot(_670, _1277);
    float _1338 = fast::clamp(_1336, 0.0, 1.0);
    float _1350 = fast::clamp(dot(_670, fast::normalize(_676 + _1277)), 0.0, 1.0);
    float _1419 = 8192.0 * fma(-_1338, _931, _1338 + _931);
    float _1423 = 1.0 / (params.facet_alpha * _1419);
    out.fragColor = float4(_1234 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1336 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1338), float3(0.0), float3(1.0))) * _951) + (_990 * ((((fma(_1423, _1419, 2.0) * pow(fast::max(fma(-_1350, _1350, 1.0), 0.0), 0.5 * (_1423 * _1419))) * 0.15915493667125701904296875) * (_1338 * (_1423 * _1206))) * _956))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1286 * _1286) / fast::max(_1272, 9.9999997473787516355514526367188e-05)) * _1305) * _1305)), float3(65504.0)), 1.0);
    return out;
}

