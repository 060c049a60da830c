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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _541 = fast::normalize(in.v_toEye);
    float4 _661 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _665 = (half4(_661).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1056;
    do
    {
        half3 _678 = half4(in.v_tangent).xyz;
        if (float(dot(_678, _678)) == 0.0)
        {
            _1056 = normalize(half3(in.v_normal));
            break;
        }
        _1056 = normalize(((_678 * _665.x) + ((cross(half3(in.v_normal), _678) * half(in.v_tangent.w)) * _665.y)) + (half3(in.v_normal) * _665.z));
        break;
    } while(false);
    half _748 = max(dot(_1056, half3(_541)), half(9.9999997473787516355514526367188e-05));
    float4 _787 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_748, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _806 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_787).y) - half(1.0)));
    float4 _816 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_541), _1056)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _592 = half4(frame.lightDirection).xyz;
    half3 _923 = normalize(half3(_541) + _592);
    half _874 = clamp(dot(_1056, _592), half(0.0), half(1.0));
    half4 _992 = half4(cross(_1056, _923), half(params.facet_alpha) * clamp(dot(_1056, _923), half(0.0), half(1.0))) * half(64.0);
    half _969 = half(6.283185482025146484375) * max(mix((half(2.0) * _874) * _748, _874 + _748, half(params.facet_alpha)), half(0.000244140625));
    half _971 = (half(4096.0) * half(params.facet_alpha)) / (dot(_992, _992) * _969);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_816).xyz * (mix(half4(_787).xxx, half4(_787).yyy, half3(float3(params.facet_f0))) * _806)) + min(((half3(float3(params.facet_f0)) * min(_971 * (_971 * _969), half(65504.0))) * _806) * (half4(frame.lightColor).xyz * _874), half3(float3(65504.0))), half(1.0)));
    return out;
}

