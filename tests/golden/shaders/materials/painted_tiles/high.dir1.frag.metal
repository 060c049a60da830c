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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _735 = fast::normalize(in.v_toEye);
    float2 _864 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _867 = facet_material_albedo.sample(facet_material_albedoSmplr, _864);
    float4 _877 = facet_material_relief.sample(facet_material_reliefSmplr, _864);
    half3 _881 = (half4(_877).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _887 = fract(_864 * 4.0);
    float _889 = _887.x;
    float _896 = _887.y;
    half3 _1497;
    do
    {
        half3 _921 = half4(in.v_tangent).xyz;
        if (float(dot(_921, _921)) == 0.0)
        {
            _1497 = normalize(half3(in.v_normal));
            break;
        }
        _1497 = normalize(((_921 * _881.x) + ((cross(half3(in.v_normal), _921) * half(in.v_tangent.w)) * _881.y)) + (half3(in.v_normal) * _881.z));
        break;
    } while(false);
    float4 _957 = facet_irradiance.sample(facet_irradianceSmplr, float3(_1497), level(0.0));
    half3 _981 = clamp(half4(_867).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _990 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_889, 1.0 - _889), fast::min(_896, 1.0 - _896))))), half(0.0), half(1.0));
    half _1067 = max(dot(_1497, half3(_735)), half(9.9999997473787516355514526367188e-05));
    float4 _1129 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1067, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1082 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_735), _1497)), level(params.facet_environmentLod));
    half _1200 = clamp(dot(_1497, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1280 = fast::normalize(_735 + frame.lightDirection.xyz);
    half4 _1345 = half4(cross(_1497, half3(_1280)), half(params.facet_alpha) * clamp(dot(_1497, half3(_1280)), half(0.0), half(1.0))) * half(64.0);
    half _1326 = (half(4096.0) * half(params.facet_alpha)) / dot(_1345, _1345);
    half _1370 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1280)), half(0.0), half(1.0));
    half _1373 = _1370 * _1370;
    half3 _1403 = fma(_981 * half4(_957).xyz, max(half3(_990), ((((((_981 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _990) + ((_981 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _990) + ((_981 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _990), (half4(_1082).xyz * mix(half4(_1129).xxx, half4(_1129).yyy, half3(float3(0.039999999105930328369140625)))) * _990) + min(((_981 * half(0.3183098733425140380859375)) + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1373 * _1373) * _1370))) * min(min((_1326 * _1326) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1200) * _1067, _1200 + _1067, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _1200), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1403, half(1.0)));
    return out;
}

