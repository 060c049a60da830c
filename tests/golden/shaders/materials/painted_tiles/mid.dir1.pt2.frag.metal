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
    float3 _789 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _960 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _963 = facet_material_albedo.sample(facet_material_albedoSmplr, _960);
    float4 _973 = facet_material_relief.sample(facet_material_reliefSmplr, _960);
    half3 _977 = (half4(_973).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _983 = fract(_960 * 4.0);
    float _985 = _983.x;
    float _992 = _983.y;
    half3 _2156;
    do
    {
        half3 _1017 = half4(in.v_tangent).xyz;
        if (float(dot(_1017, _1017)) == 0.0)
        {
            _2156 = normalize(half3(in.v_normal));
            break;
        }
        _2156 = normalize(((_1017 * _977.x) + ((cross(half3(in.v_normal), _1017) * half(in.v_tangent.w)) * _977.y)) + (half3(in.v_normal) * _977.z));
        break;
    } while(false);
    half3 _1060 = clamp(half4(_963).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1069 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_985, 1.0 - _985), fast::min(_992, 1.0 - _992))))), half(0.0), half(1.0));
    half _1162 = max(dot(_2156, half3(_789)), half(9.9999997473787516355514526367188e-05));
    float4 _1227 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1162, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1246 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1227).y) - half(1.0)));
    float4 _1253 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_789), _2156)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _842 = half4(frame.lightDirection).xyz;
    half3 _1390 = normalize(half3(_789) + _842);
    half _1317 = clamp(dot(_2156, _842), half(0.0), half(1.0));
    half3 _1417 = cross(_2156, _1390);
    half _1420 = clamp(dot(_2156, _1390), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1437 = max(mix((half(2.0) * _1317) * _1162, _1317 + _1162, half(params.facet_alpha)), half(0.000244140625));
    half _1439 = half(1024.0) * half(params.facet_alpha);
    half _1444 = _1439 / (fma(_1420, _1420, dot(_1417, _1417)) * (half(6433.98193359375) * _1437));
    float3 _1492 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1495 = dot(_1492, _1492);
    float3 _1500 = _1492 * rsqrt(fast::max(_1495, 9.9999999392252902907785028219223e-09));
    float _1504 = _1495 * float(frame.punctualLights[0].positionFalloff.w);
    float _1509 = fast::clamp(fma(-_1504, _1504, 1.0), 0.0, 1.0);
    float _1528 = fast::clamp(fma(dot(-_1500, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1662 = normalize(half3(_789) + half3(_1500));
    half _1589 = clamp(dot(_2156, half3(_1500)), half(0.0), half(1.0));
    half3 _1689 = cross(_2156, _1662);
    half _1692 = clamp(dot(_2156, _1662), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1709 = max(mix((half(2.0) * _1589) * _1162, _1589 + _1162, half(params.facet_alpha)), half(0.000244140625));
    half _1716 = _1439 / (fma(_1692, _1692, dot(_1689, _1689)) * (half(6433.98193359375) * _1709));
    half3 _1728 = ((fma(_1060 * half3(in.v_diffuseLight), max(half3(_1069), ((((((_1060 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1069) + ((_1060 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1069) + ((_1060 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1069), _1060 * half3(in.v_directDiffuse)) + ((half4(_1253).xyz * (mix(half4(_1227).xxx, half4(_1227).yyy, half3(float3(0.039999999105930328369140625))) * _1246)) * _1069)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1444 * (_1444 * (half(6.283185482025146484375) * _1437)), half(65504.0))) * _1246) * (half4(frame.lightColor).xyz * _1317), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1716 * (_1716 * (half(6.283185482025146484375) * _1709)), half(65504.0))) * _1246) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1509) * half(_1509)) / fast::max(_1495, 9.9999997473787516355514526367188e-05)) * half(_1528)) * half(_1528)), float3(65504.0))) * _1589), half3(float3(65504.0)));
    float3 _1764 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1767 = dot(_1764, _1764);
    float3 _1772 = _1764 * rsqrt(fast::max(_1767, 9.9999999392252902907785028219223e-09));
    float _1776 = _1767 * float(frame.punctualLights[1].positionFalloff.w);
    float _1781 = fast::clamp(fma(-_1776, _1776, 1.0), 0.0, 1.0);
    float _1800 = fast::clamp(fma(dot(-_1772, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1934 = normalize(half3(_789) + half3(_1772));
    half _1861 = clamp(dot(_2156, half3(_1772)), half(0.0), half(1.0));
    half3 _1961 = cross(_2156, _1934);
    half _1964 = clamp(dot(_2156, _1934), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1981 = max(mix((half(2.0) * _1861) * _1162, _1861 + _1162, half(params.facet_alpha)), half(0.000244140625));
    half _1988 = _1439 / (fma(_1964, _1964, dot(_1961, _1961)) * (half(6433.98193359375) * _1981));
    out.fragColor = float4(half4(_1728 + min(((half3(float3(0.039999999105930328369140625)) * min(_1988 * (_1988 * (half(6.283185482025146484375) * _1981)), half(65504.0))) * _1246) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1781) * half(_1781)) / fast::max(_1767, 9.9999997473787516355514526367188e-05)) * half(_1800)) * half(_1800)), float3(65504.0))) * _1861), half3(float3(65504.0))), half(1.0)));
    return out;
}

