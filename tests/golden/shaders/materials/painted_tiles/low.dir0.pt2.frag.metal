#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float tiling;
    float roughness;
    float facet_pad8;
    float facet_pad12;
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
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _660 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _793 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _796 = facet_material_albedo.sample(facet_material_albedoSmplr, _793);
    float4 _806 = facet_material_relief.sample(facet_material_reliefSmplr, _793);
    half3 _810 = (half4(_806).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1628;
    do
    {
        half3 _823 = half4(in.v_tangent).xyz;
        if (float(dot(_823, _823)) == 0.0)
        {
            _1628 = normalize(half3(in.v_normal));
            break;
        }
        _1628 = normalize(((_823 * _810.x) + ((cross(half3(in.v_normal), _823) * half(in.v_tangent.w)) * _810.y)) + (half3(in.v_normal) * _810.z));
        break;
    } while(false);
    half3 _905 = reflect(-half3(_660), _1628);
    float4 _965 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1628, half3(_660)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _991 = facet_environment.sample(facet_environmentSmplr, float3(_905), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _920 = mix(half4(_965).xxx, half4(_965).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_965).y) - half(1.0))));
    float3 _1036 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1039 = dot(_1036, _1036);
    float3 _1044 = _1036 * rsqrt(fast::max(_1039, 9.9999999392252902907785028219223e-09));
    float _1048 = _1039 * float(frame.punctualLights[0].positionFalloff.w);
    float _1053 = fast::clamp(fma(-_1048, _1048, 1.0), 0.0, 1.0);
    float _1072 = fast::clamp(fma(dot(-_1044, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1228 = clamp(dot(_905, half3(_1044)), half(0.0), half(1.0));
    half _1231 = _1228 * _1228;
    half4 _1704 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1231 * _1231, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1243 = _1704.x;
    float3 _1288 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1291 = dot(_1288, _1288);
    float3 _1296 = _1288 * rsqrt(fast::max(_1291, 9.9999999392252902907785028219223e-09));
    float _1300 = _1291 * float(frame.punctualLights[1].positionFalloff.w);
    float _1305 = fast::clamp(fma(-_1300, _1300, 1.0), 0.0, 1.0);
    float _1324 = fast::clamp(fma(dot(-_1296, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1480 = clamp(dot(_905, half3(_1296)), half(0.0), half(1.0));
    half _1483 = _1480 * _1480;
    half4 _1730 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1483 * _1483, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1495 = _1730.x;
    half3 _1504 = (fma(clamp(half4(_796).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_991).xyz * _920) + min((_920 * ((_1243 * _1243) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1053) * half(_1053)) / fast::max(_1039, 9.9999997473787516355514526367188e-05)) * half(_1072)) * half(_1072)), float3(65504.0))) * clamp(dot(_1628, half3(_1044)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_920 * ((_1495 * _1495) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1305) * half(_1305)) / fast::max(_1291, 9.9999997473787516355514526367188e-05)) * half(_1324)) * half(_1324)), float3(65504.0))) * clamp(dot(_1628, half3(_1296)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1504, half(1.0)));
    return out;
}

