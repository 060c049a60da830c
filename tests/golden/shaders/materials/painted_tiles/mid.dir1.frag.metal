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
    float3 _629 = fast::normalize(in.v_toEye);
    float2 _773 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _776 = facet_material_albedo.sample(facet_material_albedoSmplr, _773);
    float4 _786 = facet_material_relief.sample(facet_material_reliefSmplr, _773);
    half3 _790 = (half4(_786).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _796 = fract(_773 * 4.0);
    float _798 = _796.x;
    float _805 = _796.y;
    half3 _1314;
    do
    {
        half3 _830 = half4(in.v_tangent).xyz;
        if (float(dot(_830, _830)) == 0.0)
        {
            _1314 = normalize(half3(in.v_normal));
            break;
        }
        _1314 = normalize(((_830 * _790.x) + ((cross(half3(in.v_normal), _830) * half(in.v_tangent.w)) * _790.y)) + (half3(in.v_normal) * _790.z));
        break;
    } while(false);
    half3 _873 = clamp(half4(_776).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _879 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_798, 1.0 - _798), fast::min(_805, 1.0 - _805))))), half(0.0), half(1.0));
    half _926 = max(dot(_1314, half3(_629)), half(9.9999997473787516355514526367188e-05));
    float4 _991 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_926, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1010 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_991).y) - half(1.0)));
    float4 _1017 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_629), _1314)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _692 = half4(frame.lightDirection).xyz;
    half3 _1154 = normalize(half3(_629) + _692);
    half _1081 = clamp(dot(_1314, _692), half(0.0), half(1.0));
    half3 _1181 = cross(_1314, _1154);
    half _1184 = clamp(dot(_1314, _1154), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1201 = max(mix((half(2.0) * _1081) * _926, _1081 + _926, half(params.facet_alpha)), half(0.000244140625));
    half _1208 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1184, _1184, dot(_1181, _1181)) * (half(6433.98193359375) * _1201));
    out.fragColor = float4(half4((fma(_873, half3(in.v_directDiffuse), (_873 * half3(in.v_diffuseLight)) * _879) + ((half4(_1017).xyz * (mix(half4(_991).xxx, half4(_991).yyy, half3(float3(0.039999999105930328369140625))) * _1010)) * _879)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1208 * (_1208 * (half(6.283185482025146484375) * _1201)), half(65504.0))) * _1010) * (half4(frame.lightColor).xyz * _1081), half3(float3(65504.0))), half(1.0)));
    return out;
}

