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
    float3 _612 = fast::normalize(in.v_toEye);
    float2 _759 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _762 = facet_material_albedo.sample(facet_material_albedoSmplr, _759);
    float4 _772 = facet_material_relief.sample(facet_material_reliefSmplr, _759);
    half3 _776 = (half4(_772).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _782 = fract(_759 * 4.0);
    float _784 = _782.x;
    float _791 = _782.y;
    half3 _1275;
    do
    {
        half3 _816 = half4(in.v_tangent).xyz;
        if (float(dot(_816, _816)) == 0.0)
        {
            _1275 = normalize(half3(in.v_normal));
            break;
        }
        _1275 = normalize(((_816 * _776.x) + ((cross(half3(in.v_normal), _816) * half(in.v_tangent.w)) * _776.y)) + (half3(in.v_normal) * _776.z));
        break;
    } while(false);
    half3 _859 = clamp(half4(_762).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _865 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_784, 1.0 - _784), fast::min(_791, 1.0 - _791))))), half(0.0), half(1.0));
    half3 _916 = reflect(-half3(_612), _1275);
    float4 _978 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1275, half3(_612)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1004 = facet_environment.sample(facet_environmentSmplr, float3(_916), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _931 = mix(half4(_978).xxx, half4(_978).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_978).y) - half(1.0))));
    half3 _675 = half4(frame.lightDirection).xyz;
    half _1163 = clamp(dot(_916, _675), half(0.0), half(1.0));
    half _1166 = _1163 * _1163;
    half4 _1342 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1166 * _1166, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1178 = _1342.x;
    out.fragColor = float4(half4((fma(_859, half3(in.v_directDiffuse), (_859 * half3(in.v_diffuseLight)) * _865) + ((half4(_1004).xyz * _931) * _865)) + min((_931 * ((_1178 * _1178) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1275, _675), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

