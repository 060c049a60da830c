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
    float3 _1040 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1196 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1199 = facet_material_albedo.sample(facet_material_albedoSmplr, _1196);
    float4 _1209 = facet_material_relief.sample(facet_material_reliefSmplr, _1196);
    half3 _1213 = (half4(_1209).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1219 = fract(_1196 * 4.0);
    float _1221 = _1219.x;
    float _1228 = _1219.y;
    half3 _2804;
    do
    {
        half3 _1253 = half4(in.v_tangent).xyz;
        if (float(dot(_1253, _1253)) == 0.0)
        {
            _2804 = normalize(half3(in.v_normal));
            break;
        }
        _2804 = normalize(((_1253 * _1213.x) + ((cross(half3(in.v_normal), _1253) * half(in.v_tangent.w)) * _1213.y)) + (half3(in.v_normal) * _1213.z));
        break;
    } while(false);
    half3 _1390 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2804.y)) + (half4(frame.sh[2]).xyz * _2804.z)) + (half4(frame.sh[3]).xyz * _2804.x)) + (((((half4(frame.sh[4]).xyz * (_2804.x * _2804.y)) + (half4(frame.sh[5]).xyz * (_2804.y * _2804.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2804.z, _2804.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2804.x * _2804.z))) + (half4(frame.sh[8]).xyz * fma(_2804.x, _2804.x, half(-float(_2804.y * _2804.y))))), half3(float3(0.0)));
    half3 _1413 = clamp(half4(_1199).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1422 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1221, 1.0 - _1221), fast::min(_1228, 1.0 - _1228))))), half(0.0), half(1.0));
    half _1503 = max(dot(_2804, half3(_1040)), half(9.9999997473787516355514526367188e-05));
    float4 _1568 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1503, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1587 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1568).y) - half(1.0)));
    float4 _1597 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1040), _2804)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1769 = fast::normalize(_1040 + frame.lightDirection.xyz);
    half _1689 = clamp(dot(_2804, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1809 = half(4096.0) * half(params.facet_alpha);
    half4 _1834 = half4(cross(_2804, half3(_1769)), half(params.facet_alpha) * clamp(dot(_2804, half3(_1769)), half(0.0), half(1.0))) * half(64.0);
    half _1815 = _1809 / dot(_1834, _1834);
    half _1845 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1851 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1855 = sqrt(fma(_1503 * _1503, _1851, _1845));
    half _1879 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1769)), half(0.0), half(1.0));
    half _1882 = _1879 * _1879;
    half3 _1720 = _1413 * half(0.3183098733425140380859375);
    float3 _1948 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1951 = dot(_1948, _1948);
    float3 _1956 = _1948 * rsqrt(fast::max(_1951, 9.9999999392252902907785028219223e-09));
    float _1960 = _1951 * float(frame.punctualLights[0].positionFalloff.w);
    float _1965 = fast::clamp(fma(-_1960, _1960, 1.0), 0.0, 1.0);
    float _1984 = fast::clamp(fma(dot(-_1956, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2127 = fast::normalize(_1040 + _1956);
    half _2047 = clamp(dot(_2804, half3(_1956)), half(0.0), half(1.0));
    half4 _2192 = half4(cross(_2804, half3(_2127)), half(params.facet_alpha) * clamp(dot(_2804, half3(_2127)), half(0.0), half(1.0))) * half(64.0);
    half _2173 = _1809 / dot(_2192, _2192);
    half _2237 = half(1.0) - clamp(dot(half3(_1956), half3(_2127)), half(0.0), half(1.0));
    half _2240 = _2237 * _2237;
    half3 _2270 = (fma(_1413 * _1390, max(half3(_1422), ((((((_1413 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1422) + ((_1413 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1422) + ((_1413 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1422), (half4(_1597).xyz * (mix(half4(_1568).xxx, half4(_1568).yyy, half3(float3(0.039999999105930328369140625))) * _1587)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1503 + _1422)) - half(1.0)) + _1422, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1882 * _1882) * _1879))) * min(min((_1815 * _1815) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1689, _1855, _1503 * sqrt(fma(_1689 * _1689, _1851, _1845))), half(65504.0)), half(65504.0)), _1587, _1720) * (half4(frame.lightColor).xyz * _1689), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2240 * _2240) * _2237))) * min(min((_2173 * _2173) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2047, _1855, _1503 * sqrt(fma(_2047 * _2047, _1851, _1845))), half(65504.0)), half(65504.0)), _1587, _1720) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1965) * half(_1965)) / fast::max(_1951, 9.9999997473787516355514526367188e-05)) * half(_1984)) * half(_1984)), float3(65504.0))) * _2047), half3(float3(65504.0)));
    float3 _2306 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2309 = dot(_2306, _2306);
    float3 _2314 = _2306 * rsqrt(fast::max(_2309, 9.9999999392252902907785028219223e-09));
    float _2318 = _2309 * float(frame.punctualLights[1].positionFalloff.w);
    float _2323 = fast::clamp(fma(-_2318, _2318, 1.0), 0.0, 1.0);
    float _2342 = fast::clamp(fma(dot(-_2314, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2485 = fast::normalize(_1040 + _2314);
    half _2405 = clamp(dot(_2804, half3(_2314)), half(0.0), half(1.0));
    half4 _2550 = half4(cross(_2804, half3(_2485)), half(params.facet_alpha) * clamp(dot(_2804, half3(_2485)), half(0.0), half(1.0))) * half(64.0);
    half _2531 = _1809 / dot(_2550, _2550);
    half _2595 = half(1.0) - clamp(dot(half3(_2314), half3(_2485)), half(0.0), half(1.0));
    half _2598 = _2595 * _2595;
    half4 _2643 = half4(_2270 + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2598 * _2598) * _2595))) * min(min((_2531 * _2531) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2405, _1855, _1503 * sqrt(fma(_2405 * _2405, _1851, _1845))), half(65504.0)), half(65504.0)), _1587, _1720) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2323) * half(_2323)) / fast::max(_2309, 9.9999997473787516355514526367188e-05)) * half(_2342)) * half(_2342)), float3(65504.0))) * _2405), half3(float3(65504.0))), half(1.0));
    out.fragColor = float4(_2643);
    return out;
}

