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
    float3 _938 = fast::normalize(in.v_toEye);
    float2 _1057 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1060 = facet_material_albedo.sample(facet_material_albedoSmplr, _1057);
    float4 _1070 = facet_material_relief.sample(facet_material_reliefSmplr, _1057);
    half3 _1074 = (half4(_1070).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1080 = fract(_1057 * 4.0);
    float _1082 = _1080.x;
    float _1089 = _1080.y;
    half3 _1883;
    do
    {
        half3 _1114 = half4(in.v_tangent).xyz;
        if (float(dot(_1114, _1114)) == 0.0)
        {
            _1883 = normalize(half3(in.v_normal));
            break;
        }
        _1883 = normalize(((_1114 * _1074.x) + ((cross(half3(in.v_normal), _1114) * half(in.v_tangent.w)) * _1074.y)) + (half3(in.v_normal) * _1074.z));
        break;
    } while(false);
    half3 _1251 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1883.y)) + (half4(frame.sh[2]).xyz * _1883.z)) + (half4(frame.sh[3]).xyz * _1883.x)) + (((((half4(frame.sh[4]).xyz * (_1883.x * _1883.y)) + (half4(frame.sh[5]).xyz * (_1883.y * _1883.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1883.z, _1883.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1883.x * _1883.z))) + (half4(frame.sh[8]).xyz * fma(_1883.x, _1883.x, half(-float(_1883.y * _1883.y))))), half3(float3(0.0)));
    half3 _1274 = clamp(half4(_1060).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1283 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1082, 1.0 - _1082), fast::min(_1089, 1.0 - _1089))))), half(0.0), half(1.0));
    half _1364 = max(dot(_1883, half3(_938)), half(9.9999997473787516355514526367188e-05));
    float4 _1429 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1364, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1448 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1429).y) - half(1.0)));
    float4 _1458 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_938), _1883)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1630 = fast::normalize(_938 + frame.lightDirection.xyz);
    half _1550 = clamp(dot(_1883, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1695 = half4(cross(_1883, half3(_1630)), half(params.facet_alpha) * clamp(dot(_1883, half3(_1630)), half(0.0), half(1.0))) * half(64.0);
    half _1676 = (half(4096.0) * half(params.facet_alpha)) / dot(_1695, _1695);
    half _1706 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1712 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1740 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1630)), half(0.0), half(1.0));
    half _1743 = _1740 * _1740;
    half3 _1773 = fma(_1274 * _1251, max(half3(_1283), ((((((_1274 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1283) + ((_1274 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1283) + ((_1274 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1283), (half4(_1458).xyz * (mix(half4(_1429).xxx, half4(_1429).yyy, half3(float3(0.039999999105930328369140625))) * _1448)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1364 + _1283)) - half(1.0)) + _1283, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1743 * _1743) * _1740))) * min(min((_1676 * _1676) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1550, sqrt(fma(_1364 * _1364, _1712, _1706)), _1364 * sqrt(fma(_1550 * _1550, _1712, _1706))), half(65504.0)), half(65504.0)), _1448, _1274 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1550), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1773, half(1.0)));
    return out;
}

