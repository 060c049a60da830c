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
    float2 _982 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _985 = facet_material_albedo.sample(facet_material_albedoSmplr, _982);
    float4 _995 = facet_material_relief.sample(facet_material_reliefSmplr, _982);
    half3 _999 = (half4(_995).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1005 = fract(_982 * 4.0);
    float _1007 = _1005.x;
    float _1014 = _1005.y;
    half3 _2090;
    do
    {
        half3 _1039 = half4(in.v_tangent).xyz;
        if (float(dot(_1039, _1039)) == 0.0)
        {
            _2090 = normalize(half3(in.v_normal));
            break;
        }
        _2090 = normalize(((_1039 * _999.x) + ((cross(half3(in.v_normal), _1039) * half(in.v_tangent.w)) * _999.y)) + (half3(in.v_normal) * _999.z));
        break;
    } while(false);
    float4 _1075 = facet_irradiance.sample(facet_irradianceSmplr, float3(_2090), level(0.0));
    half3 _1099 = clamp(half4(_985).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1108 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1007, 1.0 - _1007), fast::min(_1014, 1.0 - _1014))))), half(0.0), half(1.0));
    half _1185 = max(dot(_2090, half3(_847)), half(9.9999997473787516355514526367188e-05));
    float4 _1247 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1185, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1200 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_847), _2090)), level(params.facet_environmentLod));
    float3 _1306 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1309 = dot(_1306, _1306);
    float3 _1314 = _1306 * rsqrt(fast::max(_1309, 9.9999999392252902907785028219223e-09));
    float _1318 = _1309 * float(frame.punctualLights[0].positionFalloff.w);
    float _1323 = fast::clamp(fma(-_1318, _1318, 1.0), 0.0, 1.0);
    float _1342 = fast::clamp(fma(dot(-_1314, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1402 = clamp(dot(_2090, half3(_1314)), half(0.0), half(1.0));
    float3 _1482 = fast::normalize(_847 + _1314);
    half _1522 = half(4096.0) * half(params.facet_alpha);
    half4 _1547 = half4(cross(_2090, half3(_1482)), half(params.facet_alpha) * clamp(dot(_2090, half3(_1482)), half(0.0), half(1.0))) * half(64.0);
    half _1528 = _1522 / dot(_1547, _1547);
    half _1572 = half(1.0) - clamp(dot(half3(_1314), half3(_1482)), half(0.0), half(1.0));
    half _1575 = _1572 * _1572;
    half3 _1433 = _1099 * half(0.3183098733425140380859375);
    float3 _1641 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1644 = dot(_1641, _1641);
    float3 _1649 = _1641 * rsqrt(fast::max(_1644, 9.9999999392252902907785028219223e-09));
    float _1653 = _1644 * float(frame.punctualLights[1].positionFalloff.w);
    float _1658 = fast::clamp(fma(-_1653, _1653, 1.0), 0.0, 1.0);
    float _1677 = fast::clamp(fma(dot(-_1649, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1737 = clamp(dot(_2090, half3(_1649)), half(0.0), half(1.0));
    float3 _1817 = fast::normalize(_847 + _1649);
    half4 _1882 = half4(cross(_2090, half3(_1817)), half(params.facet_alpha) * clamp(dot(_2090, half3(_1817)), half(0.0), half(1.0))) * half(64.0);
    half _1863 = _1522 / dot(_1882, _1882);
    half _1907 = half(1.0) - clamp(dot(half3(_1649), half3(_1817)), half(0.0), half(1.0));
    half _1910 = _1907 * _1907;
    half3 _1940 = (fma(_1099 * half4(_1075).xyz, max(half3(_1108), ((((((_1099 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1108) + ((_1099 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1108) + ((_1099 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1108), (half4(_1200).xyz * mix(half4(_1247).xxx, half4(_1247).yyy, half3(float3(0.039999999105930328369140625)))) * _1108) + min((_1433 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1575 * _1575) * _1572))) * min(min((_1528 * _1528) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1402) * _1185, _1402 + _1185, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1323) * half(_1323)) / fast::max(_1309, 9.9999997473787516355514526367188e-05)) * half(_1342)) * half(_1342)), float3(65504.0))) * _1402), half3(float3(65504.0)))) + min((_1433 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1910 * _1910) * _1907))) * min(min((_1863 * _1863) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1737) * _1185, _1737 + _1185, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1658) * half(_1658)) / fast::max(_1644, 9.9999997473787516355514526367188e-05)) * half(_1677)) * half(_1677)), float3(65504.0))) * _1737), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1940, half(1.0)));
    return out;
}

