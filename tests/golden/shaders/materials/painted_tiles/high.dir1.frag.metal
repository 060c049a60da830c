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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _922 = fast::normalize(in.v_toEye);
    float2 _1041 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1044 = facet_material_albedo.sample(facet_material_albedoSmplr, _1041);
    float4 _1054 = facet_material_relief.sample(facet_material_reliefSmplr, _1041);
    half3 _1058 = (half4(_1054).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1064 = fract(_1041 * 4.0);
    float _1066 = _1064.x;
    float _1073 = _1064.y;
    half3 _1859;
    do
    {
        half3 _1098 = half4(in.v_tangent).xyz;
        if (float(dot(_1098, _1098)) == 0.0)
        {
            _1859 = normalize(half3(in.v_normal));
            break;
        }
        _1859 = normalize(((_1098 * _1058.x) + ((cross(half3(in.v_normal), _1098) * half(in.v_tangent.w)) * _1058.y)) + (half3(in.v_normal) * _1058.z));
        break;
    } while(false);
    half3 _1235 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1859.y)) + (half4(frame.sh[2]).xyz * _1859.z)) + (half4(frame.sh[3]).xyz * _1859.x)) + (((((half4(frame.sh[4]).xyz * (_1859.x * _1859.y)) + (half4(frame.sh[5]).xyz * (_1859.y * _1859.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1859.z, _1859.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1859.x * _1859.z))) + (half4(frame.sh[8]).xyz * fma(_1859.x, _1859.x, half(-float(_1859.y * _1859.y))))), half3(float3(0.0)));
    half3 _1258 = clamp(half4(_1044).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1267 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1066, 1.0 - _1066), fast::min(_1073, 1.0 - _1073))))), half(0.0), half(1.0));
    half _1348 = max(dot(_1859, half3(_922)), half(9.9999997473787516355514526367188e-05));
    float4 _1413 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1348, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1432 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1413).y) - half(1.0)));
    float4 _1444 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_922), _1859)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1616 = fast::normalize(_922 + frame.lightDirection.xyz);
    half _1536 = clamp(dot(_1859, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1656 = cross(_1859, half3(_1616));
    half _1659 = clamp(dot(_1859, half3(_1616)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1668 = half(params.facet_alpha) / fma(_1659, _1659, dot(_1656, _1656));
    half _1682 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1688 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1716 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1616)), half(0.0), half(1.0));
    half _1719 = _1716 * _1716;
    half3 _1749 = fma(_1258 * _1235, max(half3(_1267), ((((((_1258 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1267) + ((_1258 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1267) + ((_1258 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1267), (half4(_1444).xyz * (mix(half4(_1413).xxx, half4(_1413).yyy, half3(float3(0.039999999105930328369140625))) * _1432)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1348 + _1267)) - half(1.0)) + _1267, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1719 * _1719) * _1716))) * min(min((_1668 * _1668) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1536, sqrt(fma(_1348 * _1348, _1688, _1682)), _1348 * sqrt(fma(_1536 * _1536, _1688, _1682))), half(65504.0)), half(65504.0)), _1432, _1258 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1536), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1749, half(1.0)));
    return out;
}

