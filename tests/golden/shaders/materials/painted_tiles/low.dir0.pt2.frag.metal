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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _737 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _890 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _893 = facet_material_albedo.sample(facet_material_albedoSmplr, _890);
    float4 _903 = facet_material_relief.sample(facet_material_reliefSmplr, _890);
    half3 _907 = (half4(_903).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _913 = fract(_890 * 4.0);
    float _915 = _913.x;
    float _922 = _913.y;
    half3 _1815;
    do
    {
        half3 _947 = half4(in.v_tangent).xyz;
        if (float(dot(_947, _947)) == 0.0)
        {
            _1815 = normalize(half3(in.v_normal));
            break;
        }
        _1815 = normalize(((_947 * _907.x) + ((cross(half3(in.v_normal), _947) * half(in.v_tangent.w)) * _907.y)) + (half3(in.v_normal) * _907.z));
        break;
    } while(false);
    half3 _990 = clamp(half4(_893).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _999 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_915, 1.0 - _915), fast::min(_922, 1.0 - _922))))), half(0.0), half(1.0));
    half3 _1092 = reflect(-half3(_737), _1815);
    float4 _1151 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1815, half3(_737)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1160 = mix(half4(_1151).xxx, half4(_1151).yyy, half3(float3(0.039999999105930328369140625)));
    float4 _1103 = facet_environment.sample(facet_environmentSmplr, float3(_1092), level(params.facet_environmentLod));
    float3 _1210 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1213 = dot(_1210, _1210);
    float3 _1218 = _1210 * rsqrt(fast::max(_1213, 9.9999999392252902907785028219223e-09));
    float _1222 = _1213 * float(frame.punctualLights[0].positionFalloff.w);
    float _1227 = fast::clamp(fma(-_1222, _1222, 1.0), 0.0, 1.0);
    float _1246 = fast::clamp(fma(dot(-_1218, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1402 = clamp(dot(_1092, half3(_1218)), half(0.0), half(1.0));
    half _1405 = _1402 * _1402;
    half4 _1897 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1405 * _1405, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1417 = _1897.x;
    float3 _1462 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1465 = dot(_1462, _1462);
    float3 _1470 = _1462 * rsqrt(fast::max(_1465, 9.9999999392252902907785028219223e-09));
    float _1474 = _1465 * float(frame.punctualLights[1].positionFalloff.w);
    float _1479 = fast::clamp(fma(-_1474, _1474, 1.0), 0.0, 1.0);
    float _1498 = fast::clamp(fma(dot(-_1470, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1654 = clamp(dot(_1092, half3(_1470)), half(0.0), half(1.0));
    half _1657 = _1654 * _1654;
    half4 _1923 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1657 * _1657, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1669 = _1923.x;
    half3 _1678 = ((fma(_990 * half3(in.v_diffuseLight), max(half3(_999), ((((((_990 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _999) + ((_990 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _999) + ((_990 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _999), _990 * half3(in.v_directDiffuse)) + ((half4(_1103).xyz * _1160) * _999)) + min((_1160 * ((_1417 * _1417) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1227) * half(_1227)) / fast::max(_1213, 9.9999997473787516355514526367188e-05)) * half(_1246)) * half(_1246)), float3(65504.0))) * clamp(dot(_1815, half3(_1218)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1160 * ((_1669 * _1669) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1479) * half(_1479)) / fast::max(_1465, 9.9999997473787516355514526367188e-05)) * half(_1498)) * half(_1498)), float3(65504.0))) * clamp(dot(_1815, half3(_1470)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1678, half(1.0)));
    return out;
}

