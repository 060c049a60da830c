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
    float2 _790 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _793 = facet_material_albedo.sample(facet_material_albedoSmplr, _790);
    float4 _803 = facet_material_relief.sample(facet_material_reliefSmplr, _790);
    half3 _807 = (half4(_803).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1625;
    do
    {
        half3 _820 = half4(in.v_tangent).xyz;
        if (float(dot(_820, _820)) == 0.0)
        {
            _1625 = normalize(half3(in.v_normal));
            break;
        }
        _1625 = normalize(((_820 * _807.x) + ((cross(half3(in.v_normal), _820) * half(in.v_tangent.w)) * _807.y)) + (half3(in.v_normal) * _807.z));
        break;
    } while(false);
    half3 _902 = reflect(-half3(_660), _1625);
    float4 _962 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1625, half3(_660)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _988 = facet_environment.sample(facet_environmentSmplr, float3(_902), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _917 = mix(half4(_962).xxx, half4(_962).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_962).y) - half(1.0))));
    float3 _1033 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1036 = dot(_1033, _1033);
    float3 _1041 = _1033 * rsqrt(fast::max(_1036, 9.9999999392252902907785028219223e-09));
    float _1045 = _1036 * float(frame.punctualLights[0].positionFalloff.w);
    float _1050 = fast::clamp(fma(-_1045, _1045, 1.0), 0.0, 1.0);
    float _1069 = fast::clamp(fma(dot(-_1041, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1225 = clamp(dot(_902, half3(_1041)), half(0.0), half(1.0));
    half _1228 = _1225 * _1225;
    half4 _1701 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1228 * _1228, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1240 = _1701.x;
    float3 _1285 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1288 = dot(_1285, _1285);
    float3 _1293 = _1285 * rsqrt(fast::max(_1288, 9.9999999392252902907785028219223e-09));
    float _1297 = _1288 * float(frame.punctualLights[1].positionFalloff.w);
    float _1302 = fast::clamp(fma(-_1297, _1297, 1.0), 0.0, 1.0);
    float _1321 = fast::clamp(fma(dot(-_1293, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1477 = clamp(dot(_902, half3(_1293)), half(0.0), half(1.0));
    half _1480 = _1477 * _1477;
    half4 _1727 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1480 * _1480, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1492 = _1727.x;
    half3 _1501 = (fma(clamp(half4(_793).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_988).xyz * _917) + min((_917 * ((_1240 * _1240) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1050) * half(_1050)) / fast::max(_1036, 9.9999997473787516355514526367188e-05)) * half(_1069)) * half(_1069)), float3(65504.0))) * clamp(dot(_1625, half3(_1041)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_917 * ((_1492 * _1492) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1302) * half(_1302)) / fast::max(_1288, 9.9999997473787516355514526367188e-05)) * half(_1321)) * half(_1321)), float3(65504.0))) * clamp(dot(_1625, half3(_1293)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1501, half(1.0)));
    return out;
}

