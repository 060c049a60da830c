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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _847 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1003 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1006 = facet_material_albedo.sample(facet_material_albedoSmplr, _1003);
    float4 _1016 = facet_material_relief.sample(facet_material_reliefSmplr, _1003);
    half3 _1020 = (half4(_1016).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1026 = fract(_1003 * 4.0);
    float _1028 = _1026.x;
    float _1035 = _1026.y;
    half3 _2372;
    do
    {
        half3 _1060 = half4(in.v_tangent).xyz;
        if (float(dot(_1060, _1060)) == 0.0)
        {
            _2372 = normalize(half3(in.v_normal));
            break;
        }
        _2372 = normalize(((_1060 * _1020.x) + ((cross(half3(in.v_normal), _1060) * half(in.v_tangent.w)) * _1020.y)) + (half3(in.v_normal) * _1020.z));
        break;
    } while(false);
    float4 _1096 = facet_irradiance.sample(facet_irradianceSmplr, float3(_2372), level(0.0));
    half3 _1120 = clamp(half4(_1006).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1129 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1028, 1.0 - _1028), fast::min(_1035, 1.0 - _1035))))), half(0.0), half(1.0));
    half _1206 = max(dot(_2372, half3(_847)), half(9.9999997473787516355514526367188e-05));
    float4 _1268 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1206, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1221 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_847), _2372)), level(params.facet_environmentLod));
    half _1339 = clamp(dot(_2372, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1419 = fast::normalize(_847 + frame.lightDirection.xyz);
    half _1459 = half(4096.0) * half(params.facet_alpha);
    half4 _1484 = half4(cross(_2372, half3(_1419)), half(params.facet_alpha) * clamp(dot(_2372, half3(_1419)), half(0.0), half(1.0))) * half(64.0);
    half _1465 = _1459 / dot(_1484, _1484);
    half _1509 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1419)), half(0.0), half(1.0));
    half _1512 = _1509 * _1509;
    half3 _1370 = _1120 * half(0.3183098733425140380859375);
    float3 _1578 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1581 = dot(_1578, _1578);
    float3 _1586 = _1578 * rsqrt(fast::max(_1581, 9.9999999392252902907785028219223e-09));
    float _1590 = _1581 * float(frame.punctualLights[0].positionFalloff.w);
    float _1595 = fast::clamp(fma(-_1590, _1590, 1.0), 0.0, 1.0);
    float _1614 = fast::clamp(fma(dot(-_1586, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1674 = clamp(dot(_2372, half3(_1586)), half(0.0), half(1.0));
    float3 _1754 = fast::normalize(_847 + _1586);
    half4 _1819 = half4(cross(_2372, half3(_1754)), half(params.facet_alpha) * clamp(dot(_2372, half3(_1754)), half(0.0), half(1.0))) * half(64.0);
    half _1800 = _1459 / dot(_1819, _1819);
    half _1844 = half(1.0) - clamp(dot(half3(_1586), half3(_1754)), half(0.0), half(1.0));
    half _1847 = _1844 * _1844;
    half3 _1877 = (fma(_1120 * half4(_1096).xyz, max(half3(_1129), ((((((_1120 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1129) + ((_1120 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1129) + ((_1120 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1129), (half4(_1221).xyz * mix(half4(_1268).xxx, half4(_1268).yyy, half3(float3(0.039999999105930328369140625)))) * _1129) + min((_1370 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1512 * _1512) * _1509))) * min(min((_1465 * _1465) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1339) * _1206, _1339 + _1206, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _1339), half3(float3(65504.0)))) + min((_1370 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1847 * _1847) * _1844))) * min(min((_1800 * _1800) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1674) * _1206, _1674 + _1206, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1595) * half(_1595)) / fast::max(_1581, 9.9999997473787516355514526367188e-05)) * half(_1614)) * half(_1614)), float3(65504.0))) * _1674), half3(float3(65504.0)));
    float3 _1913 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1916 = dot(_1913, _1913);
    float3 _1921 = _1913 * rsqrt(fast::max(_1916, 9.9999999392252902907785028219223e-09));
    float _1925 = _1916 * float(frame.punctualLights[1].positionFalloff.w);
    float _1930 = fast::clamp(fma(-_1925, _1925, 1.0), 0.0, 1.0);
    float _1949 = fast::clamp(fma(dot(-_1921, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _2009 = clamp(dot(_2372, half3(_1921)), half(0.0), half(1.0));
    float3 _2089 = fast::normalize(_847 + _1921);
    half4 _2154 = half4(cross(_2372, half3(_2089)), half(params.facet_alpha) * clamp(dot(_2372, half3(_2089)), half(0.0), half(1.0))) * half(64.0);
    half _2135 = _1459 / dot(_2154, _2154);
    half _2179 = half(1.0) - clamp(dot(half3(_1921), half3(_2089)), half(0.0), half(1.0));
    half _2182 = _2179 * _2179;
    float4 _2540 = float4(half4(_1877 + min((_1370 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2182 * _2182) * _2179))) * min(min((_2135 * _2135) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _2009) * _1206, _2009 + _1206, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1930) * half(_1930)) / fast::max(_1916, 9.9999997473787516355514526367188e-05)) * half(_1949)) * half(_1949)), float3(65504.0))) * _2009), half3(float3(65504.0))), half(1.0)));
    out.fragColor = _2540;
    return out;
}

