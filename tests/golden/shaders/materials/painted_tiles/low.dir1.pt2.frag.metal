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
    float2 _811 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _814 = facet_material_albedo.sample(facet_material_albedoSmplr, _811);
    float4 _824 = facet_material_relief.sample(facet_material_reliefSmplr, _811);
    half3 _828 = (half4(_824).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1814;
    do
    {
        half3 _841 = half4(in.v_tangent).xyz;
        if (float(dot(_841, _841)) == 0.0)
        {
            _1814 = normalize(half3(in.v_normal));
            break;
        }
        _1814 = normalize(((_841 * _828.x) + ((cross(half3(in.v_normal), _841) * half(in.v_tangent.w)) * _828.y)) + (half3(in.v_normal) * _828.z));
        break;
    } while(false);
    half3 _923 = reflect(-half3(_660), _1814);
    float4 _983 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1814, half3(_660)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1009 = facet_environment.sample(facet_environmentSmplr, float3(_923), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _938 = mix(half4(_983).xxx, half4(_983).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_983).y) - half(1.0))));
    half3 _701 = half4(frame.lightDirection).xyz;
    half _1162 = clamp(dot(_923, _701), half(0.0), half(1.0));
    half _1165 = _1162 * _1162;
    half4 _1879 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1165 * _1165, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1177 = _1879.x;
    float3 _1222 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1225 = dot(_1222, _1222);
    float3 _1230 = _1222 * rsqrt(fast::max(_1225, 9.9999999392252902907785028219223e-09));
    float _1234 = _1225 * float(frame.punctualLights[0].positionFalloff.w);
    float _1239 = fast::clamp(fma(-_1234, _1234, 1.0), 0.0, 1.0);
    float _1258 = fast::clamp(fma(dot(-_1230, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1414 = clamp(dot(_923, half3(_1230)), half(0.0), half(1.0));
    half _1417 = _1414 * _1414;
    half4 _1904 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1417 * _1417, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1429 = _1904.x;
    float3 _1474 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1477 = dot(_1474, _1474);
    float3 _1482 = _1474 * rsqrt(fast::max(_1477, 9.9999999392252902907785028219223e-09));
    float _1486 = _1477 * float(frame.punctualLights[1].positionFalloff.w);
    float _1491 = fast::clamp(fma(-_1486, _1486, 1.0), 0.0, 1.0);
    float _1510 = fast::clamp(fma(dot(-_1482, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1666 = clamp(dot(_923, half3(_1482)), half(0.0), half(1.0));
    half _1669 = _1666 * _1666;
    half4 _1930 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1669 * _1669, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1681 = _1930.x;
    half3 _1690 = ((fma(clamp(half4(_814).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1009).xyz * _938) + min((_938 * ((_1177 * _1177) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1814, _701), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_938 * ((_1429 * _1429) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1239) * half(_1239)) / fast::max(_1225, 9.9999997473787516355514526367188e-05)) * half(_1258)) * half(_1258)), float3(65504.0))) * clamp(dot(_1814, half3(_1230)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_938 * ((_1681 * _1681) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1491) * half(_1491)) / fast::max(_1477, 9.9999997473787516355514526367188e-05)) * half(_1510)) * half(_1510)), float3(65504.0))) * clamp(dot(_1814, half3(_1482)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1690, half(1.0)));
    return out;
}

