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
    float3 _1022 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1178 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1181 = facet_material_albedo.sample(facet_material_albedoSmplr, _1178);
    float4 _1191 = facet_material_relief.sample(facet_material_reliefSmplr, _1178);
    half3 _1195 = (half4(_1191).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1201 = fract(_1178 * 4.0);
    float _1203 = _1201.x;
    float _1210 = _1201.y;
    half3 _2756;
    do
    {
        half3 _1235 = half4(in.v_tangent).xyz;
        if (float(dot(_1235, _1235)) == 0.0)
        {
            _2756 = normalize(half3(in.v_normal));
            break;
        }
        _2756 = normalize(((_1235 * _1195.x) + ((cross(half3(in.v_normal), _1235) * half(in.v_tangent.w)) * _1195.y)) + (half3(in.v_normal) * _1195.z));
        break;
    } while(false);
    half3 _1372 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2756.y)) + (half4(frame.sh[2]).xyz * _2756.z)) + (half4(frame.sh[3]).xyz * _2756.x)) + (((((half4(frame.sh[4]).xyz * (_2756.x * _2756.y)) + (half4(frame.sh[5]).xyz * (_2756.y * _2756.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2756.z, _2756.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2756.x * _2756.z))) + (half4(frame.sh[8]).xyz * fma(_2756.x, _2756.x, half(-float(_2756.y * _2756.y))))), half3(float3(0.0)));
    half3 _1395 = clamp(half4(_1181).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1404 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1203, 1.0 - _1203), fast::min(_1210, 1.0 - _1210))))), half(0.0), half(1.0));
    half _1485 = max(dot(_2756, half3(_1022)), half(9.9999997473787516355514526367188e-05));
    float4 _1550 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1485, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1569 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1550).y) - half(1.0)));
    float4 _1579 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1022), _2756)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1751 = fast::normalize(_1022 + frame.lightDirection.xyz);
    half _1671 = clamp(dot(_2756, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1791 = cross(_2756, half3(_1751));
    half _1794 = clamp(dot(_2756, half3(_1751)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1803 = half(params.facet_alpha) / fma(_1794, _1794, dot(_1791, _1791));
    half _1817 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1823 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1827 = sqrt(fma(_1485 * _1485, _1823, _1817));
    half _1851 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1751)), half(0.0), half(1.0));
    half _1854 = _1851 * _1851;
    half3 _1702 = _1395 * half(0.3183098733425140380859375);
    float3 _1920 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1923 = dot(_1920, _1920);
    float3 _1928 = _1920 * rsqrt(fast::max(_1923, 9.9999999392252902907785028219223e-09));
    float _1932 = _1923 * float(frame.punctualLights[0].positionFalloff.w);
    float _1937 = fast::clamp(fma(-_1932, _1932, 1.0), 0.0, 1.0);
    float _1956 = fast::clamp(fma(dot(-_1928, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2099 = fast::normalize(_1022 + _1928);
    half _2019 = clamp(dot(_2756, half3(_1928)), half(0.0), half(1.0));
    half3 _2139 = cross(_2756, half3(_2099));
    half _2142 = clamp(dot(_2756, half3(_2099)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2151 = half(params.facet_alpha) / fma(_2142, _2142, dot(_2139, _2139));
    half _2199 = half(1.0) - clamp(dot(half3(_1928), half3(_2099)), half(0.0), half(1.0));
    half _2202 = _2199 * _2199;
    half3 _2232 = (fma(_1395 * _1372, max(half3(_1404), ((((((_1395 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1404) + ((_1395 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1404) + ((_1395 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1404), (half4(_1579).xyz * (mix(half4(_1550).xxx, half4(_1550).yyy, half3(float3(0.039999999105930328369140625))) * _1569)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1485 + _1404)) - half(1.0)) + _1404, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1854 * _1854) * _1851))) * min(min((_1803 * _1803) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1671, _1827, _1485 * sqrt(fma(_1671 * _1671, _1823, _1817))), half(65504.0)), half(65504.0)), _1569, _1702) * (half4(frame.lightColor).xyz * _1671), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2202 * _2202) * _2199))) * min(min((_2151 * _2151) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2019, _1827, _1485 * sqrt(fma(_2019 * _2019, _1823, _1817))), half(65504.0)), half(65504.0)), _1569, _1702) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1937) * half(_1937)) / fast::max(_1923, 9.9999997473787516355514526367188e-05)) * half(_1956)) * half(_1956)), float3(65504.0))) * _2019), half3(float3(65504.0)));
    float3 _2268 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2271 = dot(_2268, _2268);
    float3 _2276 = _2268 * rsqrt(fast::max(_2271, 9.9999999392252902907785028219223e-09));
    float _2280 = _2271 * float(frame.punctualLights[1].positionFalloff.w);
    float _2285 = fast::clamp(fma(-_2280, _2280, 1.0), 0.0, 1.0);
    float _2304 = fast::clamp(fma(dot(-_2276, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2447 = fast::normalize(_1022 + _2276);
    half _2367 = clamp(dot(_2756, half3(_2276)), half(0.0), half(1.0));
    half3 _2487 = cross(_2756, half3(_2447));
    half _2490 = clamp(dot(_2756, half3(_2447)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2499 = half(params.facet_alpha) / fma(_2490, _2490, dot(_2487, _2487));
    half _2547 = half(1.0) - clamp(dot(half3(_2276), half3(_2447)), half(0.0), half(1.0));
    half _2550 = _2547 * _2547;
    half4 _2595 = half4(_2232 + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2550 * _2550) * _2547))) * min(min((_2499 * _2499) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2367, _1827, _1485 * sqrt(fma(_2367 * _2367, _1823, _1817))), half(65504.0)), half(65504.0)), _1569, _1702) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2285) * half(_2285)) / fast::max(_2271, 9.9999997473787516355514526367188e-05)) * half(_2304)) * half(_2304)), float3(65504.0))) * _2367), half3(float3(65504.0))), half(1.0));
    out.fragColor = float4(_2595);
    return out;
}

