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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _756 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _796 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _799 = facet_material_albedo.sample(facet_material_albedoSmplr, _796);
    float4 _809 = facet_material_relief.sample(facet_material_reliefSmplr, _796);
    half3 _813 = (half4(_809).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _819 = fract(_796 * 4.0);
    float _821 = _819.x;
    float _828 = _819.y;
    half3 _1339;
    do
    {
        half3 _853 = half4(in.v_tangent).xyz;
        if (float(dot(_853, _853)) == 0.0)
        {
            _1339 = normalize(half3(in.v_normal));
            break;
        }
        _1339 = normalize(((_853 * _813.x) + ((cross(half3(in.v_normal), _853) * half(in.v_tangent.w)) * _813.y)) + (half3(in.v_normal) * _813.z));
        break;
    } while(false);
    half3 _896 = clamp(half4(_799).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _905 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_821, 1.0 - _821), fast::min(_828, 1.0 - _828))))), half(0.0), half(1.0));
    half3 _998 = reflect(-_756, _1339);
    float4 _1057 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1339, _756), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1066 = mix(half4(_1057).xxx, half4(_1057).yyy, half3(float3(0.039999999105930328369140625)));
    float4 _1009 = facet_environment.sample(facet_environmentSmplr, float3(_998), level(params.facet_environmentLod));
    half3 _702 = half4(frame.lightDirection).xyz;
    half _1224 = clamp(dot(_998, _702), half(0.0), half(1.0));
    half _1227 = _1224 * _1224;
    half4 _1410 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1227 * _1227, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1239 = _1410.x;
    out.fragColor = float4(half4((fma(_896 * half3(in.v_diffuseLight), max(half3(_905), ((((((_896 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _905) + ((_896 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _905) + ((_896 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _905), _896 * half3(in.v_directDiffuse)) + ((half4(_1009).xyz * _1066) * _905)) + min((_1066 * ((_1239 * _1239) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1339, _702), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

