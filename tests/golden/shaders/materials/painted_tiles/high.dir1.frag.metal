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
    float3 _935 = fast::normalize(in.v_toEye);
    float2 _1054 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1057 = facet_material_albedo.sample(facet_material_albedoSmplr, _1054);
    float4 _1067 = facet_material_relief.sample(facet_material_reliefSmplr, _1054);
    half3 _1071 = (half4(_1067).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1077 = fract(_1054 * 4.0);
    float _1079 = _1077.x;
    float _1086 = _1077.y;
    half3 _1877;
    do
    {
        half3 _1111 = half4(in.v_tangent).xyz;
        if (float(dot(_1111, _1111)) == 0.0)
        {
            _1877 = normalize(half3(in.v_normal));
            break;
        }
        _1877 = normalize(((_1111 * _1071.x) + ((cross(half3(in.v_normal), _1111) * half(in.v_tangent.w)) * _1071.y)) + (half3(in.v_normal) * _1071.z));
        break;
    } while(false);
    half3 _1248 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1877.y)) + (half4(frame.sh[2]).xyz * _1877.z)) + (half4(frame.sh[3]).xyz * _1877.x)) + (((((half4(frame.sh[4]).xyz * (_1877.x * _1877.y)) + (half4(frame.sh[5]).xyz * (_1877.y * _1877.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1877.z, _1877.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1877.x * _1877.z))) + (half4(frame.sh[8]).xyz * fma(_1877.x, _1877.x, half(-float(_1877.y * _1877.y))))), half3(float3(0.0)));
    half3 _1271 = clamp(half4(_1057).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1280 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1079, 1.0 - _1079), fast::min(_1086, 1.0 - _1086))))), half(0.0), half(1.0));
    half _1361 = max(dot(_1877, half3(_935)), half(9.9999997473787516355514526367188e-05));
    float4 _1426 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1361, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1445 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1426).y) - half(1.0)));
    float4 _1452 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_935), _1877)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1624 = fast::normalize(_935 + frame.lightDirection.xyz);
    half _1544 = clamp(dot(_1877, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1689 = half4(cross(_1877, half3(_1624)), half(params.facet_alpha) * clamp(dot(_1877, half3(_1624)), half(0.0), half(1.0))) * half(64.0);
    half _1670 = (half(4096.0) * half(params.facet_alpha)) / dot(_1689, _1689);
    half _1700 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1706 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1734 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1624)), half(0.0), half(1.0));
    half _1737 = _1734 * _1734;
    half3 _1767 = fma(_1271 * _1248, max(half3(_1280), ((((((_1271 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1280) + ((_1271 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1280) + ((_1271 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1280), (half4(_1452).xyz * (mix(half4(_1426).xxx, half4(_1426).yyy, half3(float3(0.039999999105930328369140625))) * _1445)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1361 + _1280)) - half(1.0)) + _1280, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1737 * _1737) * _1734))) * min(min((_1670 * _1670) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1544, sqrt(fma(_1361 * _1361, _1706, _1700)), _1361 * sqrt(fma(_1544 * _1544, _1706, _1700))), half(65504.0)), half(65504.0)), _1445, _1271 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1544), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1767, half(1.0)));
    return out;
}

