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
    float3 _752 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _905 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _908 = facet_material_albedo.sample(facet_material_albedoSmplr, _905);
    float4 _918 = facet_material_relief.sample(facet_material_reliefSmplr, _905);
    half3 _922 = (half4(_918).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _928 = fract(_905 * 4.0);
    float _930 = _928.x;
    float _937 = _928.y;
    half3 _1840;
    do
    {
        half3 _962 = half4(in.v_tangent).xyz;
        if (float(dot(_962, _962)) == 0.0)
        {
            _1840 = normalize(half3(in.v_normal));
            break;
        }
        _1840 = normalize(((_962 * _922.x) + ((cross(half3(in.v_normal), _962) * half(in.v_tangent.w)) * _922.y)) + (half3(in.v_normal) * _922.z));
        break;
    } while(false);
    half3 _1005 = clamp(half4(_908).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1014 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_930, 1.0 - _930), fast::min(_937, 1.0 - _937))))), half(0.0), half(1.0));
    half3 _1109 = reflect(-half3(_752), _1840);
    float4 _1165 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1840, half3(_752)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1174 = mix(half4(_1165).xxx, half4(_1165).yyy, half3(float3(0.039999999105930328369140625)));
    float4 _1184 = facet_environment.sample(facet_environmentSmplr, float3(_1109), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1235 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1238 = dot(_1235, _1235);
    float3 _1243 = _1235 * rsqrt(fast::max(_1238, 9.9999999392252902907785028219223e-09));
    float _1247 = _1238 * float(frame.punctualLights[0].positionFalloff.w);
    float _1252 = fast::clamp(fma(-_1247, _1247, 1.0), 0.0, 1.0);
    float _1271 = fast::clamp(fma(dot(-_1243, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1427 = clamp(dot(_1109, half3(_1243)), half(0.0), half(1.0));
    half _1430 = _1427 * _1427;
    half4 _1926 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1430 * _1430, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1442 = _1926.x;
    float3 _1487 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1490 = dot(_1487, _1487);
    float3 _1495 = _1487 * rsqrt(fast::max(_1490, 9.9999999392252902907785028219223e-09));
    float _1499 = _1490 * float(frame.punctualLights[1].positionFalloff.w);
    float _1504 = fast::clamp(fma(-_1499, _1499, 1.0), 0.0, 1.0);
    float _1523 = fast::clamp(fma(dot(-_1495, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1679 = clamp(dot(_1109, half3(_1495)), half(0.0), half(1.0));
    half _1682 = _1679 * _1679;
    half4 _1952 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1682 * _1682, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1694 = _1952.x;
    half3 _1703 = ((fma(_1005 * half3(in.v_diffuseLight), max(half3(_1014), ((((((_1005 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1014) + ((_1005 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1014) + ((_1005 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1014), _1005 * half3(in.v_directDiffuse)) + ((half4(_1184).xyz * _1174) * _1014)) + min((_1174 * ((_1442 * _1442) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1252) * half(_1252)) / fast::max(_1238, 9.9999997473787516355514526367188e-05)) * half(_1271)) * half(_1271)), float3(65504.0))) * clamp(dot(_1840, half3(_1243)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1174 * ((_1694 * _1694) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1504) * half(_1504)) / fast::max(_1490, 9.9999997473787516355514526367188e-05)) * half(_1523)) * half(_1523)), float3(65504.0))) * clamp(dot(_1840, half3(_1495)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1703, half(1.0)));
    return out;
}

