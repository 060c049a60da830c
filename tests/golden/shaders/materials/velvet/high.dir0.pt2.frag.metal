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
    half3 _682 = normalize(half3(in.v_normal));
    float3 _688 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _824 = _682.y;
    half _829 = _682.z;
    half _834 = _682.x;
    half3 _902 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _824)) + (half4(frame.sh[2]).xyz * _829)) + (half4(frame.sh[3]).xyz * _834)) + (((((half4(frame.sh[4]).xyz * (_834 * _824)) + (half4(frame.sh[5]).xyz * (_824 * _829))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _829, _829, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_834 * _829))) + (half4(frame.sh[8]).xyz * fma(_834, _834, half(-float(_824 * _824))))), half3(float3(0.0)));
    half _942 = max(dot(_682, half3(_688)), half(9.9999997473787516355514526367188e-05));
    float4 _947 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_942, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _998 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1709 = half4(_947);
    half _960 = _1709.z;
    half _962 = fma(half(-float(max(_998.x, max(_998.y, _998.z)))), _960, half(1.0));
    half4 _1713 = half4(_947);
    half _964 = _1713.w;
    float4 _1005 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_688), _682)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1042 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1045 = dot(_1042, _1042);
    float3 _1050 = _1042 * rsqrt(fast::max(_1045, 9.9999999392252902907785028219223e-09));
    float _1054 = _1045 * float(frame.punctualLights[0].positionFalloff.w);
    float _1059 = fast::clamp(fma(-_1054, _1054, 1.0), 0.0, 1.0);
    float _1078 = fast::clamp(fma(dot(-_1050, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1107 = dot(_682, half3(_1050));
    half _1109 = clamp(_1107, half(0.0), half(1.0));
    half _1177 = clamp(dot(_682, half3(fast::normalize(_688 + _1050))), half(0.0), half(1.0));
    half _1221 = half(8192.0) * fma(half(-float(_1109)), _942, _1109 + _942);
    half _1225 = half(1.0) / (half(params.facet_alpha) * _1221);
    half _1232 = half(2048.0) * half(params.facet_alpha);
    half3 _1143 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1107 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1109), half3(float3(0.0)), half3(float3(1.0)))) * _962) + (_998 * ((((fma(_1225, _1221, half(2.0)) * pow(max(fma(half(-float(_1177)), _1177, half(1.0)), half(0.0)), half(0.5) * (_1225 * _1221))) * half(0.15915493667125701904296875)) * (_1109 * (_1225 * _1232))) * _964))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1059) * half(_1059)) / fast::max(_1045, 9.9999997473787516355514526367188e-05)) * half(_1078)) * half(_1078)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1303 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1306 = dot(_1303, _1303);
    float3 _1311 = _1303 * rsqrt(fast::max(_1306, 9.9999999392252902907785028219223e-09));
    float _1315 = _1306 * float(frame.punctualLights[1].positionFalloff.w);
    float _1320 = fast::clamp(fma(-_1315, _1315, 1.0), 0.0, 1.0);
    float _1339 = fast::clamp(fma(dot(-_1311, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1368 = dot(_682, half3(_1311));
    half _1370 = clamp(_1368, half(0.0), half(1.0));
    half _1438 = clamp(dot(_682, half3(fast::normalize(_688 + _1311))), half(0.0), half(1.0));
    half _1482 = half(8192.0) * fma(half(-float(_1370)), _942, _1370 + _942);
    half _1486 = half(1.0) / (half(params.facet_alpha) * _1482);
    half3 _1404 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1368 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1370), half3(float3(0.0)), half3(float3(1.0)))) * _962) + (_998 * ((((fma(_1486, _1482, half(2.0)) * pow(max(fma(half(-float(_1438)), _1438, half(1.0)), half(0.0)), half(0.5) * (_1486 * _1482))) * half(0.15915493667125701904296875)) * (_1370 * (_1486 * _1232))) * _964))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1320) * half(_1320)) / fast::max(_1306, 9.9999997473787516355514526367188e-05)) * half(_1339)) * half(_1339)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1005).xyz, _998 * _960, (half3(float3(params.facet_diffuseColor)) * _902) * _962) + _1143) + _1404, half(1.0)));
    return out;
}

