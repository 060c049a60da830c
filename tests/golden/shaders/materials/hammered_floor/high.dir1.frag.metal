#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float tiling;
    float roughness;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _660 = fast::normalize(in.v_toEye);
    float4 _784 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _788 = (half4(_784).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1341;
    do
    {
        half3 _801 = half4(in.v_tangent).xyz;
        if (float(dot(_801, _801)) == 0.0)
        {
            _1341 = normalize(half3(in.v_normal));
            break;
        }
        _1341 = normalize(((_801 * _788.x) + ((cross(half3(in.v_normal), _801) * half(in.v_tangent.w)) * _788.y)) + (half3(in.v_normal) * _788.z));
        break;
    } while(false);
    half _837 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _847 = dfdx(float3(_1341));
    float3 _849 = dfdy(float3(_1341));
    half _860 = _837 * _837;
    float4 _877 = facet_irradiance.sample(facet_irradianceSmplr, float3(_1341), level(0.0));
    half _953 = clamp(half(sqrt(sqrt(fast::min(fma(float(_860), float(_860), fast::min((dot(_847, _847) + dot(_849, _849)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _926 = max(dot(_1341, half3(_660)), half(9.9999997473787516355514526367188e-05));
    float4 _960 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_926, _953)), level(0.0));
    float4 _979 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_660), _1341)), level(_953 * (half(4.0) * (half(2.0) - _953))));
    half _1091 = _953 * _953;
    half _1036 = clamp(dot(_1341, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1103 = fast::normalize(_660 + frame.lightDirection.xyz);
    half4 _1168 = half4(cross(_1341, half3(_1103)), _1091 * clamp(dot(_1341, half3(_1103)), half(0.0), half(1.0))) * half(64.0);
    half _1149 = (half(4096.0) * _1091) / dot(_1168, _1168);
    half _1179 = _1091 * _1091;
    half _1185 = fma(half(-float(_1091)), _1091, half(1.0));
    half _1213 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1103)), half(0.0), half(1.0));
    half _1216 = _1213 * _1213;
    half3 _1238 = fma(half3(float3(params.facet_diffuseColor)), half4(_877).xyz, half4(_979).xyz * mix(half4(_960).xxx, half4(_960).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) + ((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1216 * _1216) * _1213))) * min(min((_1149 * _1149) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1036, sqrt(fma(_926 * _926, _1185, _1179)), _926 * sqrt(fma(_1036 * _1036, _1185, _1179))), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _1036), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1238, half(1.0)));
    return out;
}

