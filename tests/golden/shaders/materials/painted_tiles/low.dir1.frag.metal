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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _660 = fast::normalize(in.v_toEye);
    float2 _807 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _810 = facet_material_albedo.sample(facet_material_albedoSmplr, _807);
    float4 _820 = facet_material_relief.sample(facet_material_reliefSmplr, _807);
    half3 _824 = (half4(_820).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _830 = fract(_807 * 4.0);
    float _832 = _830.x;
    float _839 = _830.y;
    half3 _1376;
    do
    {
        half3 _864 = half4(in.v_tangent).xyz;
        if (float(dot(_864, _864)) == 0.0)
        {
            _1376 = normalize(half3(in.v_normal));
            break;
        }
        _1376 = normalize(((_864 * _824.x) + ((cross(half3(in.v_normal), _864) * half(in.v_tangent.w)) * _824.y)) + (half3(in.v_normal) * _824.z));
        break;
    } while(false);
    half3 _907 = clamp(half4(_810).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _916 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_832, 1.0 - _832), fast::min(_839, 1.0 - _839))))), half(0.0), half(1.0));
    half3 _1013 = reflect(-half3(_660), _1376);
    float4 _1075 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1376, half3(_660)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1101 = facet_environment.sample(facet_environmentSmplr, float3(_1013), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1028 = mix(half4(_1075).xxx, half4(_1075).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1075).y) - half(1.0))));
    half3 _723 = half4(frame.lightDirection).xyz;
    half _1260 = clamp(dot(_1013, _723), half(0.0), half(1.0));
    half _1263 = _1260 * _1260;
    half4 _1452 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1263 * _1263, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1275 = _1452.x;
    out.fragColor = float4(half4((fma(_907 * half3(in.v_diffuseLight), max(half3(_916), ((((((_907 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _916) + ((_907 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _916) + ((_907 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _916), _907 * half3(in.v_directDiffuse)) + ((half4(_1101).xyz * _1028) * _916)) + min((_1028 * ((_1275 * _1275) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1376, _723), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

