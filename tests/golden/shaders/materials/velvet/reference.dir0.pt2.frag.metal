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
    float3 _644 = fast::normalize(in.v_normal);
    float3 _650 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _786 = _644.y;
    float _791 = _644.z;
    float _796 = _644.x;
    float _904 = fast::max(dot(_644, _650), 9.9999997473787516355514526367188e-05);
    float4 _909 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_904, params.facet_perceptualRoughness), level(0.0));
    float3 _955 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _922 = _909.z;
    float _924 = fma(-fast::max(_955.x, fast::max(_955.y, _955.z)), _922, 1.0);
    float _926 = _909.w;
    float3 _998 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1001 = dot(_998, _998);
    float3 _1006 = _998 * rsqrt(fast::max(_1001, 9.9999999392252902907785028219223e-09));
    float _1010 = _1001 * float(frame.punctualLights[0].positionFalloff.w);
    float _1015 = fast::clamp(fma(-_1010, _1010, 1.0), 0.0, 1.0);
    float _1034 = fast::clamp(fma(dot(-_1006, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1069 = dot(_644, _1006);
    float _1071 = fast::clamp(_1069, 0.0, 1.0);
    float _1085 = fast::clamp(dot(_644, fast::normalize(_650 + _1006)), 0.0, 1.0);
    float _1167 = 2.0 + (1.0 / params.facet_alpha);
    float _1170 = 0.5 / params.facet_alpha;
    float3 _1196 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_650, _644), level(params.facet_perceptualRoughness * 4.0)).xyz, _955 * _922, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _786)) + (frame.sh[2].xyz * _791)) + (frame.sh[3].xyz * _796)) + (((((frame.sh[4].xyz * (_796 * _786)) + (frame.sh[5].xyz * (_786 * _791))) + (frame.sh[6].xyz * fma(3.0 * _791, _791, -1.0))) + (frame.sh[7].xyz * (_796 * _791))) + (frame.sh[8].xyz * fma(_796, _796, -(_786 * _786)))), float3(0.0))) * _924) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1069 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1071), float3(0.0), float3(1.0))) * _924) + (_955 * ((((_1167 * pow(fast::max(fma(-_1085, _1085, 1.0), 0.0), _1170)) * 0.15915493667125701904296875) * (_1071 / (4.0 * fma(-_1071, _904, _1071 + _904)))) * _926))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1015 * _1015) / fast::max(_1001, 9.9999997473787516355514526367188e-05)) * _1034) * _1034)), float3(65504.0));
    float3 _1231 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1234 = dot(_1231, _1231);
    float3 _1239 = _1231 * rsqrt(fast::max(_1234, 9.9999999392252902907785028219223e-09));
    float _1243 = _1234 * float(frame.punctualLights[1].positionFalloff.w);
    float _1248 = fast::clamp(fma(-_1243, _1243, 1.0), 0.0, 1.0);
    float _1267 = fast::clamp(fma(dot(-_1239, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1302 = dot(_644, _1239);
    float _1304 = fast::clamp(_1302, 0.0, 1.0);
    float _1318 = fast::clamp(dot(_644, fast::normalize(_650 + _1239)), 0.0, 1.0);
    out.fragColor = float4(_1196 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1302 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1304), float3(0.0), float3(1.0))) * _924) + (_955 * ((((_1167 * pow(fast::max(fma(-_1318, _1318, 1.0), 0.0), _1170)) * 0.15915493667125701904296875) * (_1304 / (4.0 * fma(-_1304, _904, _1304 + _904)))) * _926))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1248 * _1248) / fast::max(_1234, 9.9999997473787516355514526367188e-05)) * _1267) * _1267)), float3(65504.0)), 1.0);
    return out;
}

