#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    float3 _766 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _872 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _921 = _759.y;
    float _926 = _759.z;
    float _931 = _759.x;
    float3 _1022 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_872)), float3(0.0), float3(1.0)) * 1.0;
    float _1097 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _872), 0.0, 1.0);
    float3 _1105 = float3((0.1599999964237213134765625 * _1097) * _1097);
    float _1114 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _872), 0.08900000154972076416015625, 1.0);
    float _1057 = fast::max(dot(_759, _766), 9.9999997473787516355514526367188e-05);
    float4 _1121 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1057, _1114), level(0.0));
    float3 _1140 = float3(1.0) + (_1105 * ((1.0 / _1121.y) - 1.0));
    float _1289 = _1114 * _1114;
    float _1207 = fast::clamp(dot(_759, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1300 = fast::normalize(_766 + frame.lightDirection.xyz);
    float4 _1362 = float4(cross(_759, _1300), _1289 * fast::clamp(dot(_759, _1300), 0.0, 1.0)) * 64.0;
    float _1344 = (4096.0 * _1289) / dot(_1362, _1362);
    float _1373 = _1289 * _1289;
    float _1379 = fma(-_1289, _1289, 1.0);
    float _1406 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1300), 0.0, 1.0);
    float _1409 = _1406 * _1406;
    float3 _1439 = fma(_1022, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _921)) + (frame.sh[2].xyz * _926)) + (frame.sh[3].xyz * _931)) + (((((frame.sh[4].xyz * (_931 * _921)) + (frame.sh[5].xyz * (_921 * _926))) + (frame.sh[6].xyz * fma(3.0 * _926, _926, -1.0))) + (frame.sh[7].xyz * (_931 * _926))) + (frame.sh[8].xyz * fma(_931, _931, -(_921 * _921)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_766, _759), level(_1114 * (4.0 * (2.0 - _1114)))).xyz * (mix(_1121.xxx, _1121.yyy, _1105) * _1140)) + fast::min(fma((_1105 + ((float3(1.0) - _1105) * ((_1409 * _1409) * _1406))) * (((_1344 * _1344) * 0.3183098733425140380859375) * (0.5 / fma(_1207, sqrt(fma(_1057 * _1057, _1379, _1373)), _1057 * sqrt(fma(_1207 * _1207, _1379, _1373))))), _1140, _1022 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1207), float3(65504.0));
    out.fragColor = float4(_1439, 1.0);
    return out;
}

