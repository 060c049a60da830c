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
    float3 _1019 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1175 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1178 = facet_material_albedo.sample(facet_material_albedoSmplr, _1175);
    float4 _1188 = facet_material_relief.sample(facet_material_reliefSmplr, _1175);
    half3 _1192 = (half4(_1188).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1198 = fract(_1175 * 4.0);
    float _1200 = _1198.x;
    float _1207 = _1198.y;
    half3 _2750;
    do
    {
        half3 _1232 = half4(in.v_tangent).xyz;
        if (float(dot(_1232, _1232)) == 0.0)
        {
            _2750 = normalize(half3(in.v_normal));
            break;
        }
        _2750 = normalize(((_1232 * _1192.x) + ((cross(half3(in.v_normal), _1232) * half(in.v_tangent.w)) * _1192.y)) + (half3(in.v_normal) * _1192.z));
        break;
    } while(false);
    half3 _1369 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2750.y)) + (half4(frame.sh[2]).xyz * _2750.z)) + (half4(frame.sh[3]).xyz * _2750.x)) + (((((half4(frame.sh[4]).xyz * (_2750.x * _2750.y)) + (half4(frame.sh[5]).xyz * (_2750.y * _2750.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2750.z, _2750.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2750.x * _2750.z))) + (half4(frame.sh[8]).xyz * fma(_2750.x, _2750.x, half(-float(_2750.y * _2750.y))))), half3(float3(0.0)));
    half3 _1392 = clamp(half4(_1178).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1401 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1200, 1.0 - _1200), fast::min(_1207, 1.0 - _1207))))), half(0.0), half(1.0));
    half _1482 = max(dot(_2750, half3(_1019)), half(9.9999997473787516355514526367188e-05));
    float4 _1547 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1482, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1566 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1547).y) - half(1.0)));
    float4 _1573 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1019), _2750)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1745 = fast::normalize(_1019 + frame.lightDirection.xyz);
    half _1665 = clamp(dot(_2750, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1785 = cross(_2750, half3(_1745));
    half _1788 = clamp(dot(_2750, half3(_1745)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1797 = half(params.facet_alpha) / fma(_1788, _1788, dot(_1785, _1785));
    half _1811 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1817 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1821 = sqrt(fma(_1482 * _1482, _1817, _1811));
    half _1845 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1745)), half(0.0), half(1.0));
    half _1848 = _1845 * _1845;
    half3 _1696 = _1392 * half(0.3183098733425140380859375);
    float3 _1914 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1917 = dot(_1914, _1914);
    float3 _1922 = _1914 * rsqrt(fast::max(_1917, 9.9999999392252902907785028219223e-09));
    float _1926 = _1917 * float(frame.punctualLights[0].positionFalloff.w);
    float _1931 = fast::clamp(fma(-_1926, _1926, 1.0), 0.0, 1.0);
    float _1950 = fast::clamp(fma(dot(-_1922, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2093 = fast::normalize(_1019 + _1922);
    half _2013 = clamp(dot(_2750, half3(_1922)), half(0.0), half(1.0));
    half3 _2133 = cross(_2750, half3(_2093));
    half _2136 = clamp(dot(_2750, half3(_2093)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2145 = half(params.facet_alpha) / fma(_2136, _2136, dot(_2133, _2133));
    half _2193 = half(1.0) - clamp(dot(half3(_1922), half3(_2093)), half(0.0), half(1.0));
    half _2196 = _2193 * _2193;
    half3 _2226 = (fma(_1392 * _1369, max(half3(_1401), ((((((_1392 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1401) + ((_1392 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1401) + ((_1392 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1401), (half4(_1573).xyz * (mix(half4(_1547).xxx, half4(_1547).yyy, half3(float3(0.039999999105930328369140625))) * _1566)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1482 + _1401)) - half(1.0)) + _1401, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1848 * _1848) * _1845))) * min(min((_1797 * _1797) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1665, _1821, _1482 * sqrt(fma(_1665 * _1665, _1817, _1811))), half(65504.0)), half(65504.0)), _1566, _1696) * (half4(frame.lightColor).xyz * _1665), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2196 * _2196) * _2193))) * min(min((_2145 * _2145) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2013, _1821, _1482 * sqrt(fma(_2013 * _2013, _1817, _1811))), half(65504.0)), half(65504.0)), _1566, _1696) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1931) * half(_1931)) / fast::max(_1917, 9.9999997473787516355514526367188e-05)) * half(_1950)) * half(_1950)), float3(65504.0))) * _2013), half3(float3(65504.0)));
    float3 _2262 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2265 = dot(_2262, _2262);
    float3 _2270 = _2262 * rsqrt(fast::max(_2265, 9.9999999392252902907785028219223e-09));
    float _2274 = _2265 * float(frame.punctualLights[1].positionFalloff.w);
    float _2279 = fast::clamp(fma(-_2274, _2274, 1.0), 0.0, 1.0);
    float _2298 = fast::clamp(fma(dot(-_2270, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2441 = fast::normalize(_1019 + _2270);
    half _2361 = clamp(dot(_2750, half3(_2270)), half(0.0), half(1.0));
    half3 _2481 = cross(_2750, half3(_2441));
    half _2484 = clamp(dot(_2750, half3(_2441)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2493 = half(params.facet_alpha) / fma(_2484, _2484, dot(_2481, _2481));
    half _2541 = half(1.0) - clamp(dot(half3(_2270), half3(_2441)), half(0.0), half(1.0));
    half _2544 = _2541 * _2541;
    half4 _2589 = half4(_2226 + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2544 * _2544) * _2541))) * min(min((_2493 * _2493) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2361, _1821, _1482 * sqrt(fma(_2361 * _2361, _1817, _1811))), half(65504.0)), half(65504.0)), _1566, _1696) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2279) * half(_2279)) / fast::max(_2265, 9.9999997473787516355514526367188e-05)) * half(_2298)) * half(_2298)), float3(65504.0))) * _2361), half3(float3(65504.0))), half(1.0));
    out.fragColor = float4(_2589);
    return out;
}

