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
    float3 _920 = fast::normalize(in.v_toEye);
    float2 _1039 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1042 = facet_material_albedo.sample(facet_material_albedoSmplr, _1039);
    float4 _1052 = facet_material_relief.sample(facet_material_reliefSmplr, _1039);
    half3 _1056 = (half4(_1052).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1062 = fract(_1039 * 4.0);
    float _1064 = _1062.x;
    float _1071 = _1062.y;
    half3 _1855;
    do
    {
        half3 _1096 = half4(in.v_tangent).xyz;
        if (float(dot(_1096, _1096)) == 0.0)
        {
            _1855 = normalize(half3(in.v_normal));
            break;
        }
        _1855 = normalize(((_1096 * _1056.x) + ((cross(half3(in.v_normal), _1096) * half(in.v_tangent.w)) * _1056.y)) + (half3(in.v_normal) * _1056.z));
        break;
    } while(false);
    half3 _1233 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1855.y)) + (half4(frame.sh[2]).xyz * _1855.z)) + (half4(frame.sh[3]).xyz * _1855.x)) + (((((half4(frame.sh[4]).xyz * (_1855.x * _1855.y)) + (half4(frame.sh[5]).xyz * (_1855.y * _1855.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1855.z, _1855.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1855.x * _1855.z))) + (half4(frame.sh[8]).xyz * fma(_1855.x, _1855.x, half(-float(_1855.y * _1855.y))))), half3(float3(0.0)));
    half3 _1256 = clamp(half4(_1042).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1265 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1064, 1.0 - _1064), fast::min(_1071, 1.0 - _1071))))), half(0.0), half(1.0));
    half _1346 = max(dot(_1855, half3(_920)), half(9.9999997473787516355514526367188e-05));
    float4 _1411 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1346, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1430 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1411).y) - half(1.0)));
    float4 _1440 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_920), _1855)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1612 = fast::normalize(_920 + frame.lightDirection.xyz);
    half _1532 = clamp(dot(_1855, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1652 = cross(_1855, half3(_1612));
    half _1655 = clamp(dot(_1855, half3(_1612)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1664 = half(params.facet_alpha) / fma(_1655, _1655, dot(_1652, _1652));
    half _1678 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1684 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1712 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1612)), half(0.0), half(1.0));
    half _1715 = _1712 * _1712;
    half3 _1745 = fma(_1256 * _1233, max(half3(_1265), ((((((_1256 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1265) + ((_1256 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1265) + ((_1256 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1265), (half4(_1440).xyz * (mix(half4(_1411).xxx, half4(_1411).yyy, half3(float3(0.039999999105930328369140625))) * _1430)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1346 + _1265)) - half(1.0)) + _1265, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1715 * _1715) * _1712))) * min(min((_1664 * _1664) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1532, sqrt(fma(_1346 * _1346, _1684, _1678)), _1346 * sqrt(fma(_1532 * _1532, _1684, _1678))), half(65504.0)), half(65504.0)), _1430, _1256 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1532), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1745, half(1.0)));
    return out;
}

