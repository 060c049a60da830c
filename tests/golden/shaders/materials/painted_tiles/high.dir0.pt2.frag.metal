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
    float2 _1154 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1157 = facet_material_albedo.sample(facet_material_albedoSmplr, _1154);
    float4 _1167 = facet_material_relief.sample(facet_material_reliefSmplr, _1154);
    half3 _1171 = (half4(_1167).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1177 = fract(_1154 * 4.0);
    float _1179 = _1177.x;
    float _1186 = _1177.y;
    half3 _2455;
    do
    {
        half3 _1211 = half4(in.v_tangent).xyz;
        if (float(dot(_1211, _1211)) == 0.0)
        {
            _2455 = normalize(half3(in.v_normal));
            break;
        }
        _2455 = normalize(((_1211 * _1171.x) + ((cross(half3(in.v_normal), _1211) * half(in.v_tangent.w)) * _1171.y)) + (half3(in.v_normal) * _1171.z));
        break;
    } while(false);
    half3 _1348 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2455.y)) + (half4(frame.sh[2]).xyz * _2455.z)) + (half4(frame.sh[3]).xyz * _2455.x)) + (((((half4(frame.sh[4]).xyz * (_2455.x * _2455.y)) + (half4(frame.sh[5]).xyz * (_2455.y * _2455.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2455.z, _2455.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2455.x * _2455.z))) + (half4(frame.sh[8]).xyz * fma(_2455.x, _2455.x, half(-float(_2455.y * _2455.y))))), half3(float3(0.0)));
    half3 _1371 = clamp(half4(_1157).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1380 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1179, 1.0 - _1179), fast::min(_1186, 1.0 - _1186))))), half(0.0), half(1.0));
    half _1461 = max(dot(_2455, half3(_1019)), half(9.9999997473787516355514526367188e-05));
    float4 _1526 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1461, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1545 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1526).y) - half(1.0)));
    float4 _1552 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1019), _2455)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1629 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1632 = dot(_1629, _1629);
    float3 _1637 = _1629 * rsqrt(fast::max(_1632, 9.9999999392252902907785028219223e-09));
    float _1641 = _1632 * float(frame.punctualLights[0].positionFalloff.w);
    float _1646 = fast::clamp(fma(-_1641, _1641, 1.0), 0.0, 1.0);
    float _1665 = fast::clamp(fma(dot(-_1637, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1808 = fast::normalize(_1019 + _1637);
    half _1728 = clamp(dot(_2455, half3(_1637)), half(0.0), half(1.0));
    half3 _1848 = cross(_2455, half3(_1808));
    half _1851 = clamp(dot(_2455, half3(_1808)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1860 = half(params.facet_alpha) / fma(_1851, _1851, dot(_1848, _1848));
    half _1874 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1880 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1884 = sqrt(fma(_1461 * _1461, _1880, _1874));
    half _1908 = half(1.0) - clamp(dot(half3(_1637), half3(_1808)), half(0.0), half(1.0));
    half _1911 = _1908 * _1908;
    half3 _1759 = _1371 * half(0.3183098733425140380859375);
    float3 _1977 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1980 = dot(_1977, _1977);
    float3 _1985 = _1977 * rsqrt(fast::max(_1980, 9.9999999392252902907785028219223e-09));
    float _1989 = _1980 * float(frame.punctualLights[1].positionFalloff.w);
    float _1994 = fast::clamp(fma(-_1989, _1989, 1.0), 0.0, 1.0);
    float _2013 = fast::clamp(fma(dot(-_1985, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2156 = fast::normalize(_1019 + _1985);
    half _2076 = clamp(dot(_2455, half3(_1985)), half(0.0), half(1.0));
    half3 _2196 = cross(_2455, half3(_2156));
    half _2199 = clamp(dot(_2455, half3(_2156)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2208 = half(params.facet_alpha) / fma(_2199, _2199, dot(_2196, _2196));
    half _2256 = half(1.0) - clamp(dot(half3(_1985), half3(_2156)), half(0.0), half(1.0));
    half _2259 = _2256 * _2256;
    half3 _2289 = (fma(_1371 * _1348, max(half3(_1380), ((((((_1371 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1380) + ((_1371 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1380) + ((_1371 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1380), (half4(_1552).xyz * (mix(half4(_1526).xxx, half4(_1526).yyy, half3(float3(0.039999999105930328369140625))) * _1545)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1461 + _1380)) - half(1.0)) + _1380, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1911 * _1911) * _1908))) * min(min((_1860 * _1860) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1728, _1884, _1461 * sqrt(fma(_1728 * _1728, _1880, _1874))), half(65504.0)), half(65504.0)), _1545, _1759) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1646) * half(_1646)) / fast::max(_1632, 9.9999997473787516355514526367188e-05)) * half(_1665)) * half(_1665)), float3(65504.0))) * _1728), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2259 * _2259) * _2256))) * min(min((_2208 * _2208) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2076, _1884, _1461 * sqrt(fma(_2076 * _2076, _1880, _1874))), half(65504.0)), half(65504.0)), _1545, _1759) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1994) * half(_1994)) / fast::max(_1980, 9.9999997473787516355514526367188e-05)) * half(_2013)) * half(_2013)), float3(65504.0))) * _2076), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2289, half(1.0)));
    return out;
}

