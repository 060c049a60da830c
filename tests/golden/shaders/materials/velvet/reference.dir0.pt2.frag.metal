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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _653 = fast::normalize(in.v_normal);
    float3 _659 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _795 = _653.y;
    float _800 = _653.z;
    float _805 = _653.x;
    float _912 = fast::max(dot(_653, _659), 9.9999997473787516355514526367188e-05);
    float4 _917 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_912, params.facet_perceptualRoughness), level(0.0));
    float _930 = _917.z;
    float _932 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _930, 1.0);
    float _937 = _917.w;
    float3 _1015 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1018 = dot(_1015, _1015);
    float3 _1023 = _1015 * rsqrt(fast::max(_1018, 9.9999999392252902907785028219223e-09));
    float _1027 = _1018 * float(frame.punctualLights[0].positionFalloff.w);
    float _1032 = fast::clamp(fma(-_1027, _1027, 1.0), 0.0, 1.0);
    float _1051 = fast::clamp(fma(dot(-_1023, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1082 = dot(_653, _1023);
    float _1084 = fast::clamp(_1082, 0.0, 1.0);
    float _1096 = fast::clamp(dot(_653, fast::normalize(_659 + _1023)), 0.0, 1.0);
    float _1165 = 8192.0 * fma(-_1084, _912, _1084 + _912);
    float _1169 = 1.0 / (params.facet_alpha * _1165);
    float _1176 = 2048.0 * params.facet_alpha;
    float3 _1204 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_659, _653), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _930, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _795)) + (frame.sh[2].xyz * _800)) + (frame.sh[3].xyz * _805)) + (((((frame.sh[4].xyz * (_805 * _795)) + (frame.sh[5].xyz * (_795 * _800))) + (frame.sh[6].xyz * fma(3.0 * _800, _800, -1.0))) + (frame.sh[7].xyz * (_805 * _800))) + (frame.sh[8].xyz * fma(_805, _805, -(_795 * _795)))), float3(0.0))) * _932) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1082 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1084), float3(0.0), float3(1.0))) * _932) + (float3(params.facet_sheenColor) * ((((fma(_1169, _1165, 2.0) * pow(fast::max(fma(-_1096, _1096, 1.0), 0.0), 0.5 * (_1169 * _1165))) * 0.15915493667125701904296875) * (_1084 * (_1169 * _1176))) * _937))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1032 * _1032) / fast::max(_1018, 9.9999997473787516355514526367188e-05)) * _1051) * _1051)), float3(65504.0));
    float3 _1239 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1242 = dot(_1239, _1239);
    float3 _1247 = _1239 * rsqrt(fast::max(_1242, 9.9999999392252902907785028219223e-09));
    float _1251 = _1242 * float(frame.punctualLights[1].positionFalloff.w);
    float _1256 = fast::clamp(fma(-_1251, _1251, 1.0), 0.0, 1.0);
    float _1275 = fast::clamp(fma(dot(-_1247, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1306 = dot(_653, _1247);
    float _1308 = fast::clamp(_1306, 0.0, 1.0);
    float _1320 = fast::clamp(dot(_653, fast::normalize(_659 + _1247)), 0.0, 1.0);
    float _1389 = 8192.0 * fma(-_1308, _912, _1308 + _912);
    float _1393 = 1.0 / (params.facet_alpha * _1389);
    out.fragColor = float4(_1204 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1306 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1308), float3(0.0), float3(1.0))) * _932) + (float3(params.facet_sheenColor) * ((((fma(_1393, _1389, 2.0) * pow(fast::max(fma(-_1320, _1320, 1.0), 0.0), 0.5 * (_1393 * _1389))) * 0.15915493667125701904296875) * (_1308 * (_1393 * _1176))) * _937))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1256 * _1256) / fast::max(_1242, 9.9999997473787516355514526367188e-05)) * _1275) * _1275)), float3(65504.0)), 1.0);
    return out;
}

