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
    float2 _1180 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1183 = facet_material_albedo.sample(facet_material_albedoSmplr, _1180);
    float4 _1193 = facet_material_relief.sample(facet_material_reliefSmplr, _1180);
    half3 _1197 = (half4(_1193).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1203 = fract(_1180 * 4.0);
    float _1205 = _1203.x;
    float _1212 = _1203.y;
    half3 _2760;
    do
    {
        half3 _1237 = half4(in.v_tangent).xyz;
        if (float(dot(_1237, _1237)) == 0.0)
        {
            _2760 = normalize(half3(in.v_normal));
            break;
        }
        _2760 = normalize(((_1237 * _1197.x) + ((cross(half3(in.v_normal), _1237) * half(in.v_tangent.w)) * _1197.y)) + (half3(in.v_normal) * _1197.z));
        break;
    } while(false);
    half3 _1374 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2760.y)) + (half4(frame.sh[2]).xyz * _2760.z)) + (half4(frame.sh[3]).xyz * _2760.x)) + (((((half4(frame.sh[4]).xyz * (_2760.x * _2760.y)) + (half4(frame.sh[5]).xyz * (_2760.y * _2760.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2760.z, _2760.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2760.x * _2760.z))) + (half4(frame.sh[8]).xyz * fma(_2760.x, _2760.x, half(-float(_2760.y * _2760.y))))), half3(float3(0.0)));
    half3 _1397 = clamp(half4(_1183).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1406 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1205, 1.0 - _1205), fast::min(_1212, 1.0 - _1212))))), half(0.0), half(1.0));
    half _1487 = max(dot(_2760, half3(_1024)), half(9.9999997473787516355514526367188e-05));
    float4 _1552 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1487, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1571 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1552).y) - half(1.0)));
    float4 _1583 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1024), _2760)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1755 = fast::normalize(_1024 + frame.lightDirection.xyz);
    half _1675 = clamp(dot(_2760, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1795 = cross(_2760, half3(_1755));
    half _1798 = clamp(dot(_2760, half3(_1755)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1807 = half(params.facet_alpha) / fma(_1798, _1798, dot(_1795, _1795));
    half _1821 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1827 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1831 = sqrt(fma(_1487 * _1487, _1827, _1821));
    half _1855 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1755)), half(0.0), half(1.0));
    half _1858 = _1855 * _1855;
    half3 _1706 = _1397 * half(0.3183098733425140380859375);
    float3 _1924 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1927 = dot(_1924, _1924);
    float3 _1932 = _1924 * rsqrt(fast::max(_1927, 9.9999999392252902907785028219223e-09));
    float _1936 = _1927 * float(frame.punctualLights[0].positionFalloff.w);
    float _1941 = fast::clamp(fma(-_1936, _1936, 1.0), 0.0, 1.0);
    float _1960 = fast::clamp(fma(dot(-_1932, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2103 = fast::normalize(_1024 + _1932);
    half _2023 = clamp(dot(_2760, half3(_1932)), half(0.0), half(1.0));
    half3 _2143 = cross(_2760, half3(_2103));
    half _2146 = clamp(dot(_2760, half3(_2103)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2155 = half(params.facet_alpha) / fma(_2146, _2146, dot(_2143, _2143));
    half _2203 = half(1.0) - clamp(dot(half3(_1932), half3(_2103)), half(0.0), half(1.0));
    half _2206 = _2203 * _2203;
    half3 _2236 = (fma(_1397 * _1374, max(half3(_1406), ((((((_1397 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1406) + ((_1397 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1406) + ((_1397 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1406), (half4(_1583).xyz * (mix(half4(_1552).xxx, half4(_1552).yyy, half3(float3(0.039999999105930328369140625))) * _1571)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1487 + _1406)) - half(1.0)) + _1406, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1858 * _1858) * _1855))) * min(min((_1807 * _1807) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1675, _1831, _1487 * sqrt(fma(_1675 * _1675, _1827, _1821))), half(65504.0)), half(65504.0)), _1571, _1706) * (half4(frame.lightColor).xyz * _1675), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2206 * _2206) * _2203))) * min(min((_2155 * _2155) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2023, _1831, _1487 * sqrt(fma(_2023 * _2023, _1827, _1821))), half(65504.0)), half(65504.0)), _1571, _1706) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1941) * half(_1941)) / fast::max(_1927, 9.9999997473787516355514526367188e-05)) * half(_1960)) * half(_1960)), float3(65504.0))) * _2023), half3(float3(65504.0)));
    float3 _2272 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2275 = dot(_2272, _2272);
    float3 _2280 = _2272 * rsqrt(fast::max(_2275, 9.9999999392252902907785028219223e-09));
    float _2284 = _2275 * float(frame.punctualLights[1].positionFalloff.w);
    float _2289 = fast::clamp(fma(-_2284, _2284, 1.0), 0.0, 1.0);
    float _2308 = fast::clamp(fma(dot(-_2280, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2451 = fast::normalize(_1024 + _2280);
    half _2371 = clamp(dot(_2760, half3(_2280)), half(0.0), half(1.0));
    half3 _2491 = cross(_2760, half3(_2451));
    half _2494 = clamp(dot(_2760, half3(_2451)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2503 = half(params.facet_alpha) / fma(_2494, _2494, dot(_2491, _2491));
    half _2551 = half(1.0) - clamp(dot(half3(_2280), half3(_2451)), half(0.0), half(1.0));
    half _2554 = _2551 * _2551;
    half4 _2599 = half4(_2236 + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2554 * _2554) * _2551))) * min(min((_2503 * _2503) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2371, _1831, _1487 * sqrt(fma(_2371 * _2371, _1827, _1821))), half(65504.0)), half(65504.0)), _1571, _1706) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2289) * half(_2289)) / fast::max(_2275, 9.9999997473787516355514526367188e-05)) * half(_2308)) * half(_2308)), float3(65504.0))) * _2371), half3(float3(65504.0))), half(1.0));
    out.fragColor = float4(_2599);
    return out;
}

