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
    float3 _809 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _980 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _983 = facet_material_albedo.sample(facet_material_albedoSmplr, _980);
    float4 _993 = facet_material_relief.sample(facet_material_reliefSmplr, _980);
    half3 _997 = (half4(_993).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1003 = fract(_980 * 4.0);
    float _1005 = _1003.x;
    float _1012 = _1003.y;
    half3 _2215;
    do
    {
        half3 _1037 = half4(in.v_tangent).xyz;
        if (float(dot(_1037, _1037)) == 0.0)
        {
            _2215 = normalize(half3(in.v_normal));
            break;
        }
        _2215 = normalize(((_1037 * _997.x) + ((cross(half3(in.v_normal), _1037) * half(in.v_tangent.w)) * _997.y)) + (half3(in.v_normal) * _997.z));
        break;
    } while(false);
    half3 _1080 = clamp(half4(_983).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1089 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1005, 1.0 - _1005), fast::min(_1012, 1.0 - _1012))))), half(0.0), half(1.0));
    half _1182 = max(dot(_2215, half3(_809)), half(9.9999997473787516355514526367188e-05));
    float4 _1247 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1182, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1266 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1247).y) - half(1.0)));
    float4 _1273 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_809), _2215)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _862 = half4(frame.lightDirection).xyz;
    half3 _1410 = normalize(half3(_809) + _862);
    half _1337 = clamp(dot(_2215, _862), half(0.0), half(1.0));
    half3 _1473 = cross(_2215, _1410) * half(64.0);
    half _1476 = half(64.0) * half(params.facet_alpha);
    half _1477 = clamp(dot(_2215, _1410), half(0.0), half(1.0)) * _1476;
    half _1453 = half(4096.0) * half(params.facet_alpha);
    half _1456 = half(6.283185482025146484375) * max(mix((half(2.0) * _1337) * _1182, _1337 + _1182, half(params.facet_alpha)), half(0.000244140625));
    half _1458 = _1453 / (fma(_1477, _1477, dot(_1473, _1473)) * _1456);
    float3 _1525 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1528 = dot(_1525, _1525);
    float3 _1533 = _1525 * rsqrt(fast::max(_1528, 9.9999999392252902907785028219223e-09));
    float _1537 = _1528 * float(frame.punctualLights[0].positionFalloff.w);
    float _1542 = fast::clamp(fma(-_1537, _1537, 1.0), 0.0, 1.0);
    float _1561 = fast::clamp(fma(dot(-_1533, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1695 = normalize(half3(_809) + half3(_1533));
    half _1622 = clamp(dot(_2215, half3(_1533)), half(0.0), half(1.0));
    half3 _1758 = cross(_2215, _1695) * half(64.0);
    half _1762 = clamp(dot(_2215, _1695), half(0.0), half(1.0)) * _1476;
    half _1741 = half(6.283185482025146484375) * max(mix((half(2.0) * _1622) * _1182, _1622 + _1182, half(params.facet_alpha)), half(0.000244140625));
    half _1743 = _1453 / (fma(_1762, _1762, dot(_1758, _1758)) * _1741);
    half3 _1774 = ((fma(_1080 * half3(in.v_diffuseLight), max(half3(_1089), ((((((_1080 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1089) + ((_1080 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1089) + ((_1080 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1089), _1080 * half3(in.v_directDiffuse)) + ((half4(_1273).xyz * (mix(half4(_1247).xxx, half4(_1247).yyy, half3(float3(0.039999999105930328369140625))) * _1266)) * _1089)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1458 * (_1458 * _1456), half(65504.0))) * _1266) * (half4(frame.lightColor).xyz * _1337), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1743 * (_1743 * _1741), half(65504.0))) * _1266) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1542) * half(_1542)) / fast::max(_1528, 9.9999997473787516355514526367188e-05)) * half(_1561)) * half(_1561)), float3(65504.0))) * _1622), half3(float3(65504.0)));
    float3 _1810 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1813 = dot(_1810, _1810);
    float3 _1818 = _1810 * rsqrt(fast::max(_1813, 9.9999999392252902907785028219223e-09));
    float _1822 = _1813 * float(frame.punctualLights[1].positionFalloff.w);
    float _1827 = fast::clamp(fma(-_1822, _1822, 1.0), 0.0, 1.0);
    float _1846 = fast::clamp(fma(dot(-_1818, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1980 = normalize(half3(_809) + half3(_1818));
    half _1907 = clamp(dot(_2215, half3(_1818)), half(0.0), half(1.0));
    half3 _2043 = cross(_2215, _1980) * half(64.0);
    half _2047 = clamp(dot(_2215, _1980), half(0.0), half(1.0)) * _1476;
    half _2026 = half(6.283185482025146484375) * max(mix((half(2.0) * _1907) * _1182, _1907 + _1182, half(params.facet_alpha)), half(0.000244140625));
    half _2028 = _1453 / (fma(_2047, _2047, dot(_2043, _2043)) * _2026);
    half3 _2059 = _1774 + min(((half3(float3(0.039999999105930328369140625)) * min(_2028 * (_2028 * _2026), half(65504.0))) * _1266) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1827) * half(_1827)) / fast::max(_1813, 9.9999997473787516355514526367188e-05)) * half(_1846)) * half(_1846)), float3(65504.0))) * _1907), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2059, half(1.0)));
    return out;
}

