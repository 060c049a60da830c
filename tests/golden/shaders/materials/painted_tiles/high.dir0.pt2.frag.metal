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
    float3 _1024 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1159 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1162 = facet_material_albedo.sample(facet_material_albedoSmplr, _1159);
    float4 _1172 = facet_material_relief.sample(facet_material_reliefSmplr, _1159);
    half3 _1176 = (half4(_1172).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1182 = fract(_1159 * 4.0);
    float _1184 = _1182.x;
    float _1191 = _1182.y;
    half3 _2465;
    do
    {
        half3 _1216 = half4(in.v_tangent).xyz;
        if (float(dot(_1216, _1216)) == 0.0)
        {
            _2465 = normalize(half3(in.v_normal));
            break;
        }
        _2465 = normalize(((_1216 * _1176.x) + ((cross(half3(in.v_normal), _1216) * half(in.v_tangent.w)) * _1176.y)) + (half3(in.v_normal) * _1176.z));
        break;
    } while(false);
    half3 _1353 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2465.y)) + (half4(frame.sh[2]).xyz * _2465.z)) + (half4(frame.sh[3]).xyz * _2465.x)) + (((((half4(frame.sh[4]).xyz * (_2465.x * _2465.y)) + (half4(frame.sh[5]).xyz * (_2465.y * _2465.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2465.z, _2465.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2465.x * _2465.z))) + (half4(frame.sh[8]).xyz * fma(_2465.x, _2465.x, half(-float(_2465.y * _2465.y))))), half3(float3(0.0)));
    half3 _1376 = clamp(half4(_1162).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1385 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1184, 1.0 - _1184), fast::min(_1191, 1.0 - _1191))))), half(0.0), half(1.0));
    half _1466 = max(dot(_2465, half3(_1024)), half(9.9999997473787516355514526367188e-05));
    float4 _1531 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1466, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1550 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1531).y) - half(1.0)));
    float4 _1562 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1024), _2465)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1639 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1642 = dot(_1639, _1639);
    float3 _1647 = _1639 * rsqrt(fast::max(_1642, 9.9999999392252902907785028219223e-09));
    float _1651 = _1642 * float(frame.punctualLights[0].positionFalloff.w);
    float _1656 = fast::clamp(fma(-_1651, _1651, 1.0), 0.0, 1.0);
    float _1675 = fast::clamp(fma(dot(-_1647, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1818 = fast::normalize(_1024 + _1647);
    half _1738 = clamp(dot(_2465, half3(_1647)), half(0.0), half(1.0));
    half3 _1858 = cross(_2465, half3(_1818));
    half _1861 = clamp(dot(_2465, half3(_1818)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1870 = half(params.facet_alpha) / fma(_1861, _1861, dot(_1858, _1858));
    half _1884 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1890 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1894 = sqrt(fma(_1466 * _1466, _1890, _1884));
    half _1918 = half(1.0) - clamp(dot(half3(_1647), half3(_1818)), half(0.0), half(1.0));
    half _1921 = _1918 * _1918;
    half3 _1769 = _1376 * half(0.3183098733425140380859375);
    float3 _1987 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1990 = dot(_1987, _1987);
    float3 _1995 = _1987 * rsqrt(fast::max(_1990, 9.9999999392252902907785028219223e-09));
    float _1999 = _1990 * float(frame.punctualLights[1].positionFalloff.w);
    float _2004 = fast::clamp(fma(-_1999, _1999, 1.0), 0.0, 1.0);
    float _2023 = fast::clamp(fma(dot(-_1995, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2166 = fast::normalize(_1024 + _1995);
    half _2086 = clamp(dot(_2465, half3(_1995)), half(0.0), half(1.0));
    half3 _2206 = cross(_2465, half3(_2166));
    half _2209 = clamp(dot(_2465, half3(_2166)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2218 = half(params.facet_alpha) / fma(_2209, _2209, dot(_2206, _2206));
    half _2266 = half(1.0) - clamp(dot(half3(_1995), half3(_2166)), half(0.0), half(1.0));
    half _2269 = _2266 * _2266;
    half3 _2299 = (fma(_1376 * _1353, max(half3(_1385), ((((((_1376 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1385) + ((_1376 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1385) + ((_1376 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1385), (half4(_1562).xyz * (mix(half4(_1531).xxx, half4(_1531).yyy, half3(float3(0.039999999105930328369140625))) * _1550)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1466 + _1385)) - half(1.0)) + _1385, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1921 * _1921) * _1918))) * min(min((_1870 * _1870) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1738, _1894, _1466 * sqrt(fma(_1738 * _1738, _1890, _1884))), half(65504.0)), half(65504.0)), _1550, _1769) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1656) * half(_1656)) / fast::max(_1642, 9.9999997473787516355514526367188e-05)) * half(_1675)) * half(_1675)), float3(65504.0))) * _1738), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2269 * _2269) * _2266))) * min(min((_2218 * _2218) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2086, _1894, _1466 * sqrt(fma(_2086 * _2086, _1890, _1884))), half(65504.0)), half(65504.0)), _1550, _1769) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2004) * half(_2004)) / fast::max(_1990, 9.9999997473787516355514526367188e-05)) * half(_2023)) * half(_2023)), float3(65504.0))) * _2086), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2299, half(1.0)));
    return out;
}

