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
    float2 _960 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _963 = facet_material_albedo.sample(facet_material_albedoSmplr, _960);
    float4 _973 = facet_material_relief.sample(facet_material_reliefSmplr, _960);
    half3 _977 = (half4(_973).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _983 = fract(_960 * 4.0);
    float _985 = _983.x;
    float _992 = _983.y;
    half3 _1987;
    do
    {
        half3 _1017 = half4(in.v_tangent).xyz;
        if (float(dot(_1017, _1017)) == 0.0)
        {
            _1987 = normalize(half3(in.v_normal));
            break;
        }
        _1987 = normalize(((_1017 * _977.x) + ((cross(half3(in.v_normal), _1017) * half(in.v_tangent.w)) * _977.y)) + (half3(in.v_normal) * _977.z));
        break;
    } while(false);
    half3 _1060 = clamp(half4(_963).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1069 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_985, 1.0 - _985), fast::min(_992, 1.0 - _992))))), half(0.0), half(1.0));
    half _1162 = max(dot(_1987, half3(_810)), half(9.9999997473787516355514526367188e-05));
    float4 _1227 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1162, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1246 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1227).y) - half(1.0)));
    float4 _1256 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_810), _1987)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1307 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1310 = dot(_1307, _1307);
    float3 _1315 = _1307 * rsqrt(fast::max(_1310, 9.9999999392252902907785028219223e-09));
    float _1319 = _1310 * float(frame.punctualLights[0].positionFalloff.w);
    float _1324 = fast::clamp(fma(-_1319, _1319, 1.0), 0.0, 1.0);
    float _1343 = fast::clamp(fma(dot(-_1315, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1477 = normalize(half3(_810) + half3(_1315));
    half _1404 = clamp(dot(_1987, half3(_1315)), half(0.0), half(1.0));
    half4 _1546 = half4(cross(_1987, _1477), half(params.facet_alpha) * clamp(dot(_1987, _1477), half(0.0), half(1.0))) * half(64.0);
    half _1520 = half(4096.0) * half(params.facet_alpha);
    half _1523 = half(6.283185482025146484375) * max(mix((half(2.0) * _1404) * _1162, _1404 + _1162, half(params.facet_alpha)), half(0.000244140625));
    half _1525 = _1520 / (dot(_1546, _1546) * _1523);
    float3 _1590 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1593 = dot(_1590, _1590);
    float3 _1598 = _1590 * rsqrt(fast::max(_1593, 9.9999999392252902907785028219223e-09));
    float _1602 = _1593 * float(frame.punctualLights[1].positionFalloff.w);
    float _1607 = fast::clamp(fma(-_1602, _1602, 1.0), 0.0, 1.0);
    float _1626 = fast::clamp(fma(dot(-_1598, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1760 = normalize(half3(_810) + half3(_1598));
    half _1687 = clamp(dot(_1987, half3(_1598)), half(0.0), half(1.0));
    half4 _1829 = half4(cross(_1987, _1760), half(params.facet_alpha) * clamp(dot(_1987, _1760), half(0.0), half(1.0))) * half(64.0);
    half _1806 = half(6.283185482025146484375) * max(mix((half(2.0) * _1687) * _1162, _1687 + _1162, half(params.facet_alpha)), half(0.000244140625));
    half _1808 = _1520 / (dot(_1829, _1829) * _1806);
    half3 _1837 = ((fma(_1060 * half3(in.v_diffuseLight), max(half3(_1069), ((((((_1060 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1069) + ((_1060 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1069) + ((_1060 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1069), _1060 * half3(in.v_directDiffuse)) + ((half4(_1256).xyz * (mix(half4(_1227).xxx, half4(_1227).yyy, half3(float3(0.039999999105930328369140625))) * _1246)) * _1069)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1525 * (_1525 * _1523), half(65504.0))) * _1246) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1324) * half(_1324)) / fast::max(_1310, 9.9999997473787516355514526367188e-05)) * half(_1343)) * half(_1343)), float3(65504.0))) * _1404), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1808 * (_1808 * _1806), half(65504.0))) * _1246) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1607) * half(_1607)) / fast::max(_1593, 9.9999997473787516355514526367188e-05)) * half(_1626)) * half(_1626)), float3(65504.0))) * _1687), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1837, half(1.0)));
    return out;
}

