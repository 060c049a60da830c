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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _677 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _807 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _810 = facet_material_albedo.sample(facet_material_albedoSmplr, _807);
    float4 _820 = facet_material_relief.sample(facet_material_reliefSmplr, _807);
    half3 _824 = (half4(_820).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1693;
    do
    {
        half3 _837 = half4(in.v_tangent).xyz;
        if (float(dot(_837, _837)) == 0.0)
        {
            _1693 = normalize(half3(in.v_normal));
            break;
        }
        _1693 = normalize(((_837 * _824.x) + ((cross(half3(in.v_normal), _837) * half(in.v_tangent.w)) * _824.y)) + (half3(in.v_normal) * _824.z));
        break;
    } while(false);
    half _915 = max(dot(_1693, half3(_677)), half(9.9999997473787516355514526367188e-05));
    float4 _978 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_915, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _997 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_978).y) - half(1.0)));
    float4 _1004 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_677), _1693)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1049 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1052 = dot(_1049, _1049);
    float3 _1057 = _1049 * rsqrt(fast::max(_1052, 9.9999999392252902907785028219223e-09));
    float _1061 = _1052 * float(frame.punctualLights[0].positionFalloff.w);
    float _1066 = fast::clamp(fma(-_1061, _1061, 1.0), 0.0, 1.0);
    float _1085 = fast::clamp(fma(dot(-_1057, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1219 = normalize(half3(_677) + half3(_1057));
    half _1146 = clamp(dot(_1693, half3(_1057)), half(0.0), half(1.0));
    half3 _1246 = cross(_1693, _1219);
    half _1249 = clamp(dot(_1693, _1219), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1266 = max(mix((half(2.0) * _1146) * _915, _1146 + _915, half(params.facet_alpha)), half(0.000244140625));
    half _1268 = half(1024.0) * half(params.facet_alpha);
    half _1273 = _1268 / (fma(_1249, _1249, dot(_1246, _1246)) * (half(6433.98193359375) * _1266));
    float3 _1321 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1324 = dot(_1321, _1321);
    float3 _1329 = _1321 * rsqrt(fast::max(_1324, 9.9999999392252902907785028219223e-09));
    float _1333 = _1324 * float(frame.punctualLights[1].positionFalloff.w);
    float _1338 = fast::clamp(fma(-_1333, _1333, 1.0), 0.0, 1.0);
    float _1357 = fast::clamp(fma(dot(-_1329, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1491 = normalize(half3(_677) + half3(_1329));
    half _1418 = clamp(dot(_1693, half3(_1329)), half(0.0), half(1.0));
    half3 _1518 = cross(_1693, _1491);
    half _1521 = clamp(dot(_1693, _1491), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1538 = max(mix((half(2.0) * _1418) * _915, _1418 + _915, half(params.facet_alpha)), half(0.000244140625));
    half _1545 = _1268 / (fma(_1521, _1521, dot(_1518, _1518)) * (half(6433.98193359375) * _1538));
    half3 _1557 = (fma(clamp(half4(_810).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1004).xyz * (mix(half4(_978).xxx, half4(_978).yyy, half3(float3(0.039999999105930328369140625))) * _997)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1273 * (_1273 * (half(6.283185482025146484375) * _1266)), half(65504.0))) * _997) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1066) * half(_1066)) / fast::max(_1052, 9.9999997473787516355514526367188e-05)) * half(_1085)) * half(_1085)), float3(65504.0))) * _1146), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1545 * (_1545 * (half(6.283185482025146484375) * _1538)), half(65504.0))) * _997) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1338) * half(_1338)) / fast::max(_1324, 9.9999997473787516355514526367188e-05)) * half(_1357)) * half(_1357)), float3(65504.0))) * _1418), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1557, half(1.0)));
    return out;
}

