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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _810 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _981 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _984 = facet_material_albedo.sample(facet_material_albedoSmplr, _981);
    float4 _994 = facet_material_relief.sample(facet_material_reliefSmplr, _981);
    half3 _998 = (half4(_994).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1004 = fract(_981 * 4.0);
    float _1006 = _1004.x;
    float _1013 = _1004.y;
    half3 _2213;
    do
    {
        half3 _1038 = half4(in.v_tangent).xyz;
        if (float(dot(_1038, _1038)) == 0.0)
        {
            _2213 = normalize(half3(in.v_normal));
            break;
        }
        _2213 = normalize(((_1038 * _998.x) + ((cross(half3(in.v_normal), _1038) * half(in.v_tangent.w)) * _998.y)) + (half3(in.v_normal) * _998.z));
        break;
    } while(false);
    half3 _1081 = clamp(half4(_984).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1090 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1006, 1.0 - _1006), fast::min(_1013, 1.0 - _1013))))), half(0.0), half(1.0));
    half _1183 = max(dot(_2213, half3(_810)), half(9.9999997473787516355514526367188e-05));
    float4 _1248 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1183, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1267 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1248).y) - half(1.0)));
    float4 _1277 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_810), _2213)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _863 = half4(frame.lightDirection).xyz;
    half3 _1414 = normalize(half3(_810) + _863);
    half _1341 = clamp(dot(_2213, _863), half(0.0), half(1.0));
    half4 _1483 = half4(cross(_2213, _1414), half(params.facet_alpha) * clamp(dot(_2213, _1414), half(0.0), half(1.0))) * half(64.0);
    half _1457 = half(4096.0) * half(params.facet_alpha);
    half _1460 = half(6.283185482025146484375) * max(mix((half(2.0) * _1341) * _1183, _1341 + _1183, half(params.facet_alpha)), half(0.000244140625));
    half _1462 = _1457 / (dot(_1483, _1483) * _1460);
    float3 _1527 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1530 = dot(_1527, _1527);
    float3 _1535 = _1527 * rsqrt(fast::max(_1530, 9.9999999392252902907785028219223e-09));
    float _1539 = _1530 * float(frame.punctualLights[0].positionFalloff.w);
    float _1544 = fast::clamp(fma(-_1539, _1539, 1.0), 0.0, 1.0);
    float _1563 = fast::clamp(fma(dot(-_1535, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1697 = normalize(half3(_810) + half3(_1535));
    half _1624 = clamp(dot(_2213, half3(_1535)), half(0.0), half(1.0));
    half4 _1766 = half4(cross(_2213, _1697), half(params.facet_alpha) * clamp(dot(_2213, _1697), half(0.0), half(1.0))) * half(64.0);
    half _1743 = half(6.283185482025146484375) * max(mix((half(2.0) * _1624) * _1183, _1624 + _1183, half(params.facet_alpha)), half(0.000244140625));
    half _1745 = _1457 / (dot(_1766, _1766) * _1743);
    half3 _1774 = ((fma(_1081 * half3(in.v_diffuseLight), max(half3(_1090), ((((((_1081 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1090) + ((_1081 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1090) + ((_1081 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1090), _1081 * half3(in.v_directDiffuse)) + ((half4(_1277).xyz * (mix(half4(_1248).xxx, half4(_1248).yyy, half3(float3(0.039999999105930328369140625))) * _1267)) * _1090)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1462 * (_1462 * _1460), half(65504.0))) * _1267) * (half4(frame.lightColor).xyz * _1341), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1745 * (_1745 * _1743), half(65504.0))) * _1267) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1544) * half(_1544)) / fast::max(_1530, 9.9999997473787516355514526367188e-05)) * half(_1563)) * half(_1563)), float3(65504.0))) * _1624), half3(float3(65504.0)));
    float3 _1810 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1813 = dot(_1810, _1810);
    float3 _1818 = _1810 * rsqrt(fast::max(_1813, 9.9999999392252902907785028219223e-09));
    float _1822 = _1813 * float(frame.punctualLights[1].positionFalloff.w);
    float _1827 = fast::clamp(fma(-_1822, _1822, 1.0), 0.0, 1.0);
    float _1846 = fast::clamp(fma(dot(-_1818, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1980 = normalize(half3(_810) + half3(_1818));
    half _1907 = clamp(dot(_2213, half3(_1818)), half(0.0), half(1.0));
    half4 _2049 = half4(cross(_2213, _1980), half(params.facet_alpha) * clamp(dot(_2213, _1980), half(0.0), half(1.0))) * half(64.0);
    half _2026 = half(6.283185482025146484375) * max(mix((half(2.0) * _1907) * _1183, _1907 + _1183, half(params.facet_alpha)), half(0.000244140625));
    half _2028 = _1457 / (dot(_2049, _2049) * _2026);
    half3 _2057 = _1774 + min(((half3(float3(0.039999999105930328369140625)) * min(_2028 * (_2028 * _2026), half(65504.0))) * _1267) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1827) * half(_1827)) / fast::max(_1813, 9.9999997473787516355514526367188e-05)) * half(_1846)) * half(_1846)), float3(65504.0))) * _1907), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2057, half(1.0)));
    return out;
}

