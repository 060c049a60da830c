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
    float3 v_diffuseLight [[user(locn4)]];
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _680 = fast::normalize(in.v_toEye);
    float2 _824 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _827 = facet_material_albedo.sample(facet_material_albedoSmplr, _824);
    float4 _837 = facet_material_relief.sample(facet_material_reliefSmplr, _824);
    half3 _841 = (half4(_837).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _847 = fract(_824 * 4.0);
    float _849 = _847.x;
    float _856 = _847.y;
    half3 _1421;
    do
    {
        half3 _881 = half4(in.v_tangent).xyz;
        if (float(dot(_881, _881)) == 0.0)
        {
            _1421 = normalize(half3(in.v_normal));
            break;
        }
        _1421 = normalize(((_881 * _841.x) + ((cross(half3(in.v_normal), _881) * half(in.v_tangent.w)) * _841.y)) + (half3(in.v_normal) * _841.z));
        break;
    } while(false);
    half3 _924 = clamp(half4(_827).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _933 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_849, 1.0 - _849), fast::min(_856, 1.0 - _856))))), half(0.0), half(1.0));
    half _1026 = max(dot(_1421, half3(_680)), half(9.9999997473787516355514526367188e-05));
    float4 _1091 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1026, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1110 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1091).y) - half(1.0)));
    float4 _1120 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_680), _1421)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _743 = half4(frame.lightDirection).xyz;
    half3 _1257 = normalize(half3(_680) + _743);
    half _1184 = clamp(dot(_1421, _743), half(0.0), half(1.0));
    half3 _1284 = cross(_1421, _1257);
    half _1287 = clamp(dot(_1421, _1257), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1304 = max(mix((half(2.0) * _1184) * _1026, _1184 + _1026, half(params.facet_alpha)), half(0.000244140625));
    half _1311 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1287, _1287, dot(_1284, _1284)) * (half(6433.98193359375) * _1304));
    half3 _1323 = (fma(_924 * half3(in.v_diffuseLight), max(half3(_933), ((((((_924 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _933) + ((_924 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _933) + ((_924 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _933), _924 * half3(in.v_directDiffuse)) + ((half4(_1120).xyz * (mix(half4(_1091).xxx, half4(_1091).yyy, half3(float3(0.039999999105930328369140625))) * _1110)) * _933)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1311 * (_1311 * (half(6.283185482025146484375) * _1304)), half(65504.0))) * _1110) * (half4(frame.lightColor).xyz * _1184), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1323, half(1.0)));
    return out;
}

