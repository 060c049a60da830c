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
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _772 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _946 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _949 = facet_material_albedo.sample(facet_material_albedoSmplr, _946);
    float4 _959 = facet_material_relief.sample(facet_material_reliefSmplr, _946);
    half3 _963 = (half4(_959).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _969 = fract(_946 * 4.0);
    float _971 = _969.x;
    float _978 = _969.y;
    half3 _2065;
    do
    {
        half3 _1003 = half4(in.v_tangent).xyz;
        if (float(dot(_1003, _1003)) == 0.0)
        {
            _2065 = normalize(half3(in.v_normal));
            break;
        }
        _2065 = normalize(((_1003 * _963.x) + ((cross(half3(in.v_normal), _1003) * half(in.v_tangent.w)) * _963.y)) + (half3(in.v_normal) * _963.z));
        break;
    } while(false);
    half3 _1046 = clamp(half4(_949).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1055 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_971, 1.0 - _971), fast::min(_978, 1.0 - _978))))), half(0.0), half(1.0));
    half3 _1152 = reflect(-half3(_772), _2065);
    float4 _1214 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_2065, half3(_772)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1240 = facet_environment.sample(facet_environmentSmplr, float3(_1152), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1167 = mix(half4(_1214).xxx, half4(_1214).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1214).y) - half(1.0))));
    half3 _825 = half4(frame.lightDirection).xyz;
    half _1399 = clamp(dot(_1152, _825), half(0.0), half(1.0));
    half _1402 = _1399 * _1399;
    half4 _2143 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1402 * _1402, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1414 = _2143.x;
    float3 _1459 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1462 = dot(_1459, _1459);
    float3 _1467 = _1459 * rsqrt(fast::max(_1462, 9.9999999392252902907785028219223e-09));
    float _1471 = _1462 * float(frame.punctualLights[0].positionFalloff.w);
    float _1476 = fast::clamp(fma(-_1471, _1471, 1.0), 0.0, 1.0);
    float _1495 = fast::clamp(fma(dot(-_1467, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1651 = clamp(dot(_1152, half3(_1467)), half(0.0), half(1.0));
    half _1654 = _1651 * _1651;
    half4 _2168 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1654 * _1654, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1666 = _2168.x;
    float3 _1711 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1714 = dot(_1711, _1711);
    float3 _1719 = _1711 * rsqrt(fast::max(_1714, 9.9999999392252902907785028219223e-09));
    float _1723 = _1714 * float(frame.punctualLights[1].positionFalloff.w);
    float _1728 = fast::clamp(fma(-_1723, _1723, 1.0), 0.0, 1.0);
    float _1747 = fast::clamp(fma(dot(-_1719, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1903 = clamp(dot(_1152, half3(_1719)), half(0.0), half(1.0));
    half _1906 = _1903 * _1903;
    half4 _2194 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1906 * _1906, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1918 = _2194.x;
    half3 _1927 = (((fma(_1046 * half3(in.v_diffuseLight), max(half3(_1055), ((((((_1046 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1055) + ((_1046 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1055) + ((_1046 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1055), _1046 * half3(in.v_directDiffuse)) + ((half4(_1240).xyz * _1167) * _1055)) + min((_1167 * ((_1414 * _1414) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2065, _825), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1167 * ((_1666 * _1666) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1476) * half(_1476)) / fast::max(_1462, 9.9999997473787516355514526367188e-05)) * half(_1495)) * half(_1495)), float3(65504.0))) * clamp(dot(_2065, half3(_1467)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1167 * ((_1918 * _1918) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1728) * half(_1728)) / fast::max(_1714, 9.9999997473787516355514526367188e-05)) * half(_1747)) * half(_1747)), float3(65504.0))) * clamp(dot(_2065, half3(_1719)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1927, half(1.0)));
    return out;
}

