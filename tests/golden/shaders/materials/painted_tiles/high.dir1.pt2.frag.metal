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
    float2 _1197 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1200 = facet_material_albedo.sample(facet_material_albedoSmplr, _1197);
    float4 _1210 = facet_material_relief.sample(facet_material_reliefSmplr, _1197);
    half3 _1214 = (half4(_1210).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1220 = fract(_1197 * 4.0);
    float _1222 = _1220.x;
    float _1229 = _1220.y;
    half3 _2814;
    do
    {
        half3 _1254 = half4(in.v_tangent).xyz;
        if (float(dot(_1254, _1254)) == 0.0)
        {
            _2814 = normalize(half3(in.v_normal));
            break;
        }
        _2814 = normalize(((_1254 * _1214.x) + ((cross(half3(in.v_normal), _1254) * half(in.v_tangent.w)) * _1214.y)) + (half3(in.v_normal) * _1214.z));
        break;
    } while(false);
    half3 _1391 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2814.y)) + (half4(frame.sh[2]).xyz * _2814.z)) + (half4(frame.sh[3]).xyz * _2814.x)) + (((((half4(frame.sh[4]).xyz * (_2814.x * _2814.y)) + (half4(frame.sh[5]).xyz * (_2814.y * _2814.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2814.z, _2814.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2814.x * _2814.z))) + (half4(frame.sh[8]).xyz * fma(_2814.x, _2814.x, half(-float(_2814.y * _2814.y))))), half3(float3(0.0)));
    half3 _1414 = clamp(half4(_1200).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1423 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1222, 1.0 - _1222), fast::min(_1229, 1.0 - _1229))))), half(0.0), half(1.0));
    half _1504 = max(dot(_2814, half3(_1041)), half(9.9999997473787516355514526367188e-05));
    float4 _1569 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1504, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1588 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1569).y) - half(1.0)));
    float4 _1595 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1041), _2814)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1767 = fast::normalize(_1041 + frame.lightDirection.xyz);
    half _1687 = clamp(dot(_2814, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1808 = half(4096.0) * half(params.facet_alpha);
    half3 _1828 = cross(_2814, half3(_1767)) * half(64.0);
    half _1831 = half(64.0) * half(params.facet_alpha);
    half _1832 = clamp(dot(_2814, half3(_1767)), half(0.0), half(1.0)) * _1831;
    half _1814 = _1808 / fma(_1832, _1832, dot(_1828, _1828));
    half _1847 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1853 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1857 = sqrt(fma(_1504 * _1504, _1853, _1847));
    half _1881 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1767)), half(0.0), half(1.0));
    half _1884 = _1881 * _1881;
    half3 _1718 = _1414 * half(0.3183098733425140380859375);
    float3 _1950 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1953 = dot(_1950, _1950);
    float3 _1958 = _1950 * rsqrt(fast::max(_1953, 9.9999999392252902907785028219223e-09));
    float _1962 = _1953 * float(frame.punctualLights[0].positionFalloff.w);
    float _1967 = fast::clamp(fma(-_1962, _1962, 1.0), 0.0, 1.0);
    float _1986 = fast::clamp(fma(dot(-_1958, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2129 = fast::normalize(_1041 + _1958);
    half _2049 = clamp(dot(_2814, half3(_1958)), half(0.0), half(1.0));
    half3 _2190 = cross(_2814, half3(_2129)) * half(64.0);
    half _2194 = clamp(dot(_2814, half3(_2129)), half(0.0), half(1.0)) * _1831;
    half _2176 = _1808 / fma(_2194, _2194, dot(_2190, _2190));
    half _2243 = half(1.0) - clamp(dot(half3(_1958), half3(_2129)), half(0.0), half(1.0));
    half _2246 = _2243 * _2243;
    half3 _2276 = (fma(_1414 * _1391, max(half3(_1423), ((((((_1414 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1423) + ((_1414 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1423) + ((_1414 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1423), (half4(_1595).xyz * (mix(half4(_1569).xxx, half4(_1569).yyy, half3(float3(0.039999999105930328369140625))) * _1588)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1504 + _1423)) - half(1.0)) + _1423, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1884 * _1884) * _1881))) * min(min((_1814 * _1814) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1687, _1857, _1504 * sqrt(fma(_1687 * _1687, _1853, _1847))), half(65504.0)), half(65504.0)), _1588, _1718) * (half4(frame.lightColor).xyz * _1687), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2246 * _2246) * _2243))) * min(min((_2176 * _2176) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2049, _1857, _1504 * sqrt(fma(_2049 * _2049, _1853, _1847))), half(65504.0)), half(65504.0)), _1588, _1718) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1967) * half(_1967)) / fast::max(_1953, 9.9999997473787516355514526367188e-05)) * half(_1986)) * half(_1986)), float3(65504.0))) * _2049), half3(float3(65504.0)));
    float3 _2312 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2315 = dot(_2312, _2312);
    float3 _2320 = _2312 * rsqrt(fast::max(_2315, 9.9999999392252902907785028219223e-09));
    float _2324 = _2315 * float(frame.punctualLights[1].positionFalloff.w);
    float _2329 = fast::clamp(fma(-_2324, _2324, 1.0), 0.0, 1.0);
    float _2348 = fast::clamp(fma(dot(-_2320, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2491 = fast::normalize(_1041 + _2320);
    half _2411 = clamp(dot(_2814, half3(_2320)), half(0.0), half(1.0));
    half3 _2552 = cross(_2814, half3(_2491)) * half(64.0);
    half _2556 = clamp(dot(_2814, half3(_2491)), half(0.0), half(1.0)) * _1831;
    half _2538 = _1808 / fma(_2556, _2556, dot(_2552, _2552));
    half _2605 = half(1.0) - clamp(dot(half3(_2320), half3(_2491)), half(0.0), half(1.0));
    half _2608 = _2605 * _2605;
    half4 _2653 = half4(_2276 + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2608 * _2608) * _2605))) * min(min((_2538 * _2538) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2411, _1857, _1504 * sqrt(fma(_2411 * _2411, _1853, _1847))), half(65504.0)), half(65504.0)), _1588, _1718) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2329) * half(_2329)) / fast::max(_2315, 9.9999997473787516355514526367188e-05)) * half(_2348)) * half(_2348)), float3(65504.0))) * _2411), half3(float3(65504.0))), half(1.0));
    out.fragColor = float4(_2653);
    return out;
}

