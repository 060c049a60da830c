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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _1041 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1176 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1179 = facet_material_albedo.sample(facet_material_albedoSmplr, _1176);
    float4 _1189 = facet_material_relief.sample(facet_material_reliefSmplr, _1176);
    half3 _1193 = (half4(_1189).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1199 = fract(_1176 * 4.0);
    float _1201 = _1199.x;
    float _1208 = _1199.y;
    half3 _2505;
    do
    {
        half3 _1233 = half4(in.v_tangent).xyz;
        if (float(dot(_1233, _1233)) == 0.0)
        {
            _2505 = normalize(half3(in.v_normal));
            break;
        }
        _2505 = normalize(((_1233 * _1193.x) + ((cross(half3(in.v_normal), _1233) * half(in.v_tangent.w)) * _1193.y)) + (half3(in.v_normal) * _1193.z));
        break;
    } while(false);
    half3 _1370 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2505.y)) + (half4(frame.sh[2]).xyz * _2505.z)) + (half4(frame.sh[3]).xyz * _2505.x)) + (((((half4(frame.sh[4]).xyz * (_2505.x * _2505.y)) + (half4(frame.sh[5]).xyz * (_2505.y * _2505.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2505.z, _2505.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2505.x * _2505.z))) + (half4(frame.sh[8]).xyz * fma(_2505.x, _2505.x, half(-float(_2505.y * _2505.y))))), half3(float3(0.0)));
    half3 _1393 = clamp(half4(_1179).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1402 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1201, 1.0 - _1201), fast::min(_1208, 1.0 - _1208))))), half(0.0), half(1.0));
    half _1483 = max(dot(_2505, half3(_1041)), half(9.9999997473787516355514526367188e-05));
    float4 _1548 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1483, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1567 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1548).y) - half(1.0)));
    float4 _1574 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1041), _2505)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1651 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1654 = dot(_1651, _1651);
    float3 _1659 = _1651 * rsqrt(fast::max(_1654, 9.9999999392252902907785028219223e-09));
    float _1663 = _1654 * float(frame.punctualLights[0].positionFalloff.w);
    float _1668 = fast::clamp(fma(-_1663, _1663, 1.0), 0.0, 1.0);
    float _1687 = fast::clamp(fma(dot(-_1659, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1830 = fast::normalize(_1041 + _1659);
    half _1750 = clamp(dot(_2505, half3(_1659)), half(0.0), half(1.0));
    half _1871 = half(4096.0) * half(params.facet_alpha);
    half3 _1891 = cross(_2505, half3(_1830)) * half(64.0);
    half _1894 = half(64.0) * half(params.facet_alpha);
    half _1895 = clamp(dot(_2505, half3(_1830)), half(0.0), half(1.0)) * _1894;
    half _1877 = _1871 / fma(_1895, _1895, dot(_1891, _1891));
    half _1910 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1916 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1920 = sqrt(fma(_1483 * _1483, _1916, _1910));
    half _1944 = half(1.0) - clamp(dot(half3(_1659), half3(_1830)), half(0.0), half(1.0));
    half _1947 = _1944 * _1944;
    half3 _1781 = _1393 * half(0.3183098733425140380859375);
    float3 _2013 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2016 = dot(_2013, _2013);
    float3 _2021 = _2013 * rsqrt(fast::max(_2016, 9.9999999392252902907785028219223e-09));
    float _2025 = _2016 * float(frame.punctualLights[1].positionFalloff.w);
    float _2030 = fast::clamp(fma(-_2025, _2025, 1.0), 0.0, 1.0);
    float _2049 = fast::clamp(fma(dot(-_2021, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2192 = fast::normalize(_1041 + _2021);
    half _2112 = clamp(dot(_2505, half3(_2021)), half(0.0), half(1.0));
    half3 _2253 = cross(_2505, half3(_2192)) * half(64.0);
    half _2257 = clamp(dot(_2505, half3(_2192)), half(0.0), half(1.0)) * _1894;
    half _2239 = _1871 / fma(_2257, _2257, dot(_2253, _2253));
    half _2306 = half(1.0) - clamp(dot(half3(_2021), half3(_2192)), half(0.0), half(1.0));
    half _2309 = _2306 * _2306;
    half3 _2339 = (fma(_1393 * _1370, max(half3(_1402), ((((((_1393 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1402) + ((_1393 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1402) + ((_1393 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1402), (half4(_1574).xyz * (mix(half4(_1548).xxx, half4(_1548).yyy, half3(float3(0.039999999105930328369140625))) * _1567)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1483 + _1402)) - half(1.0)) + _1402, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1947 * _1947) * _1944))) * min(min((_1877 * _1877) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1750, _1920, _1483 * sqrt(fma(_1750 * _1750, _1916, _1910))), half(65504.0)), half(65504.0)), _1567, _1781) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1668) * half(_1668)) / fast::max(_1654, 9.9999997473787516355514526367188e-05)) * half(_1687)) * half(_1687)), float3(65504.0))) * _1750), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2309 * _2309) * _2306))) * min(min((_2239 * _2239) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2112, _1920, _1483 * sqrt(fma(_2112 * _2112, _1916, _1910))), half(65504.0)), half(65504.0)), _1567, _1781) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2030) * half(_2030)) / fast::max(_2016, 9.9999997473787516355514526367188e-05)) * half(_2049)) * half(_2049)), float3(65504.0))) * _2112), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2339, half(1.0)));
    return out;
}

