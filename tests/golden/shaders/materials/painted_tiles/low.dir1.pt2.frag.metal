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
    float2 _886 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _889 = facet_material_albedo.sample(facet_material_albedoSmplr, _886);
    float4 _899 = facet_material_relief.sample(facet_material_reliefSmplr, _886);
    half3 _903 = (half4(_899).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _909 = fract(_886 * 4.0);
    float _911 = _909.x;
    float _918 = _909.y;
    half3 _1936;
    do
    {
        half3 _943 = half4(in.v_tangent).xyz;
        if (float(dot(_943, _943)) == 0.0)
        {
            _1936 = normalize(half3(in.v_normal));
            break;
        }
        _1936 = normalize(((_943 * _903.x) + ((cross(half3(in.v_normal), _943) * half(in.v_tangent.w)) * _903.y)) + (half3(in.v_normal) * _903.z));
        break;
    } while(false);
    half _992 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_911, 1.0 - _911), fast::min(_918, 1.0 - _918))))), half(0.0), half(1.0));
    half3 _1031 = reflect(-half3(_724), _1936);
    float4 _1093 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1936, half3(_724)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1119 = facet_environment.sample(facet_environmentSmplr, float3(_1031), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1046 = mix(half4(_1093).xxx, half4(_1093).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1093).y) - half(1.0))));
    half3 _765 = half4(frame.lightDirection).xyz;
    half _1278 = clamp(dot(_1031, _765), half(0.0), half(1.0));
    half _1281 = _1278 * _1278;
    half4 _2004 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1281 * _1281, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1293 = _2004.x;
    float3 _1338 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1341 = dot(_1338, _1338);
    float3 _1346 = _1338 * rsqrt(fast::max(_1341, 9.9999999392252902907785028219223e-09));
    float _1350 = _1341 * float(frame.punctualLights[0].positionFalloff.w);
    float _1355 = fast::clamp(fma(-_1350, _1350, 1.0), 0.0, 1.0);
    float _1374 = fast::clamp(fma(dot(-_1346, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1530 = clamp(dot(_1031, half3(_1346)), half(0.0), half(1.0));
    half _1533 = _1530 * _1530;
    half4 _2029 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1533 * _1533, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1545 = _2029.x;
    float3 _1590 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1593 = dot(_1590, _1590);
    float3 _1598 = _1590 * rsqrt(fast::max(_1593, 9.9999999392252902907785028219223e-09));
    float _1602 = _1593 * float(frame.punctualLights[1].positionFalloff.w);
    float _1607 = fast::clamp(fma(-_1602, _1602, 1.0), 0.0, 1.0);
    float _1626 = fast::clamp(fma(dot(-_1598, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1782 = clamp(dot(_1031, half3(_1598)), half(0.0), half(1.0));
    half _1785 = _1782 * _1782;
    half4 _2055 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1785 * _1785, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1797 = _2055.x;
    half3 _1806 = ((((((clamp(half4(_889).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0)) * half3(in.v_diffuseLight)) * _992) + ((half4(_1119).xyz * _1046) * _992)) + min((_1046 * ((_1293 * _1293) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1936, _765), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1046 * ((_1545 * _1545) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1355) * half(_1355)) / fast::max(_1341, 9.9999997473787516355514526367188e-05)) * half(_1374)) * half(_1374)), float3(65504.0))) * clamp(dot(_1936, half3(_1346)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1046 * ((_1797 * _1797) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1607) * half(_1607)) / fast::max(_1593, 9.9999997473787516355514526367188e-05)) * half(_1626)) * half(_1626)), float3(65504.0))) * clamp(dot(_1936, half3(_1598)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1806, half(1.0)));
    return out;
}

