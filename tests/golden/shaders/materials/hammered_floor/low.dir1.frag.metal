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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _505 = fast::normalize(in.v_toEye);
    float4 _628 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _632 = (half4(_628).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _994;
    do
    {
        half3 _645 = half4(in.v_tangent).xyz;
        if (float(dot(_645, _645)) == 0.0)
        {
            _994 = normalize(half3(in.v_normal));
            break;
        }
        _994 = normalize(((_645 * _632.x) + ((cross(half3(in.v_normal), _645) * half(in.v_tangent.w)) * _632.y)) + (half3(in.v_normal) * _632.z));
        break;
    } while(false);
    half3 _719 = reflect(-half3(_505), _994);
    float4 _755 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_994, half3(_505)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _784 = facet_environment.sample(facet_environmentSmplr, float3(_719), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _734 = mix(half4(_755).xxx, half4(_755).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_755).y) - half(1.0))));
    half3 _556 = half4(frame.lightDirection).xyz;
    half _913 = clamp(dot(_719, _556), half(0.0), half(1.0));
    half _916 = _913 * _913;
    half4 _1047 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_916 * _916, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _928 = _1047.x;
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_784).xyz * _734) + min((_734 * ((_928 * _928) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_994, _556), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

