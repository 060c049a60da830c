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
    float3 _724 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _865 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _868 = facet_material_albedo.sample(facet_material_albedoSmplr, _865);
    float4 _878 = facet_material_relief.sample(facet_material_reliefSmplr, _865);
    half3 _882 = (half4(_878).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _888 = fract(_865 * 4.0);
    float _890 = _888.x;
    float _897 = _888.y;
    half3 _1747;
    do
    {
        half3 _922 = half4(in.v_tangent).xyz;
        if (float(dot(_922, _922)) == 0.0)
        {
            _1747 = normalize(half3(in.v_normal));
            break;
        }
        _1747 = normalize(((_922 * _882.x) + ((cross(half3(in.v_normal), _922) * half(in.v_tangent.w)) * _882.y)) + (half3(in.v_normal) * _882.z));
        break;
    } while(false);
    half _971 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_890, 1.0 - _890), fast::min(_897, 1.0 - _897))))), half(0.0), half(1.0));
    half3 _1010 = reflect(-half3(_724), _1747);
    float4 _1072 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1747, half3(_724)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1098 = facet_environment.sample(facet_environmentSmplr, float3(_1010), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1025 = mix(half4(_1072).xxx, half4(_1072).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1072).y) - half(1.0))));
    float3 _1149 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1152 = dot(_1149, _1149);
    float3 _1157 = _1149 * rsqrt(fast::max(_1152, 9.9999999392252902907785028219223e-09));
    float _1161 = _1152 * float(frame.punctualLights[0].positionFalloff.w);
    float _1166 = fast::clamp(fma(-_1161, _1161, 1.0), 0.0, 1.0);
    float _1185 = fast::clamp(fma(dot(-_1157, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1341 = clamp(dot(_1010, half3(_1157)), half(0.0), half(1.0));
    half _1344 = _1341 * _1341;
    half4 _1826 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1344 * _1344, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1356 = _1826.x;
    float3 _1401 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1404 = dot(_1401, _1401);
    float3 _1409 = _1401 * rsqrt(fast::max(_1404, 9.9999999392252902907785028219223e-09));
    float _1413 = _1404 * float(frame.punctualLights[1].positionFalloff.w);
    float _1418 = fast::clamp(fma(-_1413, _1413, 1.0), 0.0, 1.0);
    float _1437 = fast::clamp(fma(dot(-_1409, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1593 = clamp(dot(_1010, half3(_1409)), half(0.0), half(1.0));
    half _1596 = _1593 * _1593;
    half4 _1852 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1596 * _1596, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1608 = _1852.x;
    half3 _1617 = (((((clamp(half4(_868).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0)) * half3(in.v_diffuseLight)) * _971) + ((half4(_1098).xyz * _1025) * _971)) + min((_1025 * ((_1356 * _1356) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1166) * half(_1166)) / fast::max(_1152, 9.9999997473787516355514526367188e-05)) * half(_1185)) * half(_1185)), float3(65504.0))) * clamp(dot(_1747, half3(_1157)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1025 * ((_1608 * _1608) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1418) * half(_1418)) / fast::max(_1404, 9.9999997473787516355514526367188e-05)) * half(_1437)) * half(_1437)), float3(65504.0))) * clamp(dot(_1747, half3(_1409)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1617, half(1.0)));
    return out;
}

