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
    float2 _814 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _817 = facet_material_albedo.sample(facet_material_albedoSmplr, _814);
    float4 _827 = facet_material_relief.sample(facet_material_reliefSmplr, _814);
    half3 _831 = (half4(_827).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1817;
    do
    {
        half3 _844 = half4(in.v_tangent).xyz;
        if (float(dot(_844, _844)) == 0.0)
        {
            _1817 = normalize(half3(in.v_normal));
            break;
        }
        _1817 = normalize(((_844 * _831.x) + ((cross(half3(in.v_normal), _844) * half(in.v_tangent.w)) * _831.y)) + (half3(in.v_normal) * _831.z));
        break;
    } while(false);
    half3 _926 = reflect(-half3(_660), _1817);
    float4 _986 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1817, half3(_660)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1012 = facet_environment.sample(facet_environmentSmplr, float3(_926), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _941 = mix(half4(_986).xxx, half4(_986).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_986).y) - half(1.0))));
    half3 _701 = half4(frame.lightDirection).xyz;
    half _1165 = clamp(dot(_926, _701), half(0.0), half(1.0));
    half _1168 = _1165 * _1165;
    half4 _1882 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1168 * _1168, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1180 = _1882.x;
    float3 _1225 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1228 = dot(_1225, _1225);
    float3 _1233 = _1225 * rsqrt(fast::max(_1228, 9.9999999392252902907785028219223e-09));
    float _1237 = _1228 * float(frame.punctualLights[0].positionFalloff.w);
    float _1242 = fast::clamp(fma(-_1237, _1237, 1.0), 0.0, 1.0);
    float _1261 = fast::clamp(fma(dot(-_1233, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1417 = clamp(dot(_926, half3(_1233)), half(0.0), half(1.0));
    half _1420 = _1417 * _1417;
    half4 _1907 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1420 * _1420, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1432 = _1907.x;
    float3 _1477 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1480 = dot(_1477, _1477);
    float3 _1485 = _1477 * rsqrt(fast::max(_1480, 9.9999999392252902907785028219223e-09));
    float _1489 = _1480 * float(frame.punctualLights[1].positionFalloff.w);
    float _1494 = fast::clamp(fma(-_1489, _1489, 1.0), 0.0, 1.0);
    float _1513 = fast::clamp(fma(dot(-_1485, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1669 = clamp(dot(_926, half3(_1485)), half(0.0), half(1.0));
    half _1672 = _1669 * _1669;
    half4 _1933 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1672 * _1672, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1684 = _1933.x;
    half3 _1693 = ((fma(clamp(half4(_817).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1012).xyz * _941) + min((_941 * ((_1180 * _1180) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1817, _701), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_941 * ((_1432 * _1432) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1242) * half(_1242)) / fast::max(_1228, 9.9999997473787516355514526367188e-05)) * half(_1261)) * half(_1261)), float3(65504.0))) * clamp(dot(_1817, half3(_1233)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_941 * ((_1684 * _1684) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1494) * half(_1494)) / fast::max(_1480, 9.9999997473787516355514526367188e-05)) * half(_1513)) * half(_1513)), float3(65504.0))) * clamp(dot(_1817, half3(_1485)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1693, half(1.0)));
    return out;
}

