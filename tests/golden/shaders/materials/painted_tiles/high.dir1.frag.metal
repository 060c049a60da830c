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
    float3 _917 = fast::normalize(in.v_toEye);
    float2 _1036 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1039 = facet_material_albedo.sample(facet_material_albedoSmplr, _1036);
    float4 _1049 = facet_material_relief.sample(facet_material_reliefSmplr, _1036);
    half3 _1053 = (half4(_1049).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1059 = fract(_1036 * 4.0);
    float _1061 = _1059.x;
    float _1068 = _1059.y;
    half3 _1849;
    do
    {
        half3 _1093 = half4(in.v_tangent).xyz;
        if (float(dot(_1093, _1093)) == 0.0)
        {
            _1849 = normalize(half3(in.v_normal));
            break;
        }
        _1849 = normalize(((_1093 * _1053.x) + ((cross(half3(in.v_normal), _1093) * half(in.v_tangent.w)) * _1053.y)) + (half3(in.v_normal) * _1053.z));
        break;
    } while(false);
    half3 _1230 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1849.y)) + (half4(frame.sh[2]).xyz * _1849.z)) + (half4(frame.sh[3]).xyz * _1849.x)) + (((((half4(frame.sh[4]).xyz * (_1849.x * _1849.y)) + (half4(frame.sh[5]).xyz * (_1849.y * _1849.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1849.z, _1849.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1849.x * _1849.z))) + (half4(frame.sh[8]).xyz * fma(_1849.x, _1849.x, half(-float(_1849.y * _1849.y))))), half3(float3(0.0)));
    half3 _1253 = clamp(half4(_1039).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1262 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1061, 1.0 - _1061), fast::min(_1068, 1.0 - _1068))))), half(0.0), half(1.0));
    half _1343 = max(dot(_1849, half3(_917)), half(9.9999997473787516355514526367188e-05));
    float4 _1408 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1343, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1427 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1408).y) - half(1.0)));
    float4 _1434 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_917), _1849)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1606 = fast::normalize(_917 + frame.lightDirection.xyz);
    half _1526 = clamp(dot(_1849, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1646 = cross(_1849, half3(_1606));
    half _1649 = clamp(dot(_1849, half3(_1606)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1658 = half(params.facet_alpha) / fma(_1649, _1649, dot(_1646, _1646));
    half _1672 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1678 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1706 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1606)), half(0.0), half(1.0));
    half _1709 = _1706 * _1706;
    half3 _1739 = fma(_1253 * _1230, max(half3(_1262), ((((((_1253 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1262) + ((_1253 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1262) + ((_1253 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1262), (half4(_1434).xyz * (mix(half4(_1408).xxx, half4(_1408).yyy, half3(float3(0.039999999105930328369140625))) * _1427)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1343 + _1262)) - half(1.0)) + _1262, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1709 * _1709) * _1706))) * min(min((_1658 * _1658) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1526, sqrt(fma(_1343 * _1343, _1678, _1672)), _1343 * sqrt(fma(_1526 * _1526, _1678, _1672))), half(65504.0)), half(65504.0)), _1427, _1253 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1526), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1739, half(1.0)));
    return out;
}

