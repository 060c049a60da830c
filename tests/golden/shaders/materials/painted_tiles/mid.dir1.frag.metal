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
    float3 _695 = fast::normalize(in.v_toEye);
    float2 _839 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _842 = facet_material_albedo.sample(facet_material_albedoSmplr, _839);
    float4 _852 = facet_material_relief.sample(facet_material_reliefSmplr, _839);
    half3 _856 = (half4(_852).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _862 = fract(_839 * 4.0);
    float _864 = _862.x;
    float _871 = _862.y;
    half3 _1444;
    do
    {
        half3 _896 = half4(in.v_tangent).xyz;
        if (float(dot(_896, _896)) == 0.0)
        {
            _1444 = normalize(half3(in.v_normal));
            break;
        }
        _1444 = normalize(((_896 * _856.x) + ((cross(half3(in.v_normal), _896) * half(in.v_tangent.w)) * _856.y)) + (half3(in.v_normal) * _856.z));
        break;
    } while(false);
    half3 _939 = clamp(half4(_842).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _948 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_864, 1.0 - _864), fast::min(_871, 1.0 - _871))))), half(0.0), half(1.0));
    half _1041 = max(dot(_1444, half3(_695)), half(9.9999997473787516355514526367188e-05));
    float4 _1106 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1041, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1125 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1106).y) - half(1.0)));
    float4 _1132 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_695), _1444)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _758 = half4(frame.lightDirection).xyz;
    half3 _1269 = normalize(half3(_695) + _758);
    half _1196 = clamp(dot(_1444, _758), half(0.0), half(1.0));
    half4 _1338 = half4(cross(_1444, _1269), half(params.facet_alpha) * clamp(dot(_1444, _1269), half(0.0), half(1.0))) * half(64.0);
    half _1315 = half(6.283185482025146484375) * max(mix((half(2.0) * _1196) * _1041, _1196 + _1041, half(params.facet_alpha)), half(0.000244140625));
    half _1317 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1338, _1338) * _1315);
    half3 _1346 = (fma(_939 * half3(in.v_diffuseLight), max(half3(_948), ((((((_939 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _948) + ((_939 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _948) + ((_939 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _948), _939 * half3(in.v_directDiffuse)) + ((half4(_1132).xyz * (mix(half4(_1106).xxx, half4(_1106).yyy, half3(float3(0.039999999105930328369140625))) * _1125)) * _948)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1317 * (_1317 * _1315), half(65504.0))) * _1125) * (half4(frame.lightColor).xyz * _1196), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1346, half(1.0)));
    return out;
}

