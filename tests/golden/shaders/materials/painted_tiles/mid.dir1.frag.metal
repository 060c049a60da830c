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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _565 = fast::normalize(in.v_toEye);
    float2 _686 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _689 = facet_material_albedo.sample(facet_material_albedoSmplr, _686);
    float4 _699 = facet_material_relief.sample(facet_material_reliefSmplr, _686);
    half3 _703 = (half4(_699).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1164;
    do
    {
        half3 _716 = half4(in.v_tangent).xyz;
        if (float(dot(_716, _716)) == 0.0)
        {
            _1164 = normalize(half3(in.v_normal));
            break;
        }
        _1164 = normalize(((_716 * _703.x) + ((cross(half3(in.v_normal), _716) * half(in.v_tangent.w)) * _703.y)) + (half3(in.v_normal) * _703.z));
        break;
    } while(false);
    half _794 = max(dot(_1164, half3(_565)), half(9.9999997473787516355514526367188e-05));
    float4 _857 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_794, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _876 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_857).y) - half(1.0)));
    float4 _883 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_565), _1164)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _616 = half4(frame.lightDirection).xyz;
    half3 _1014 = normalize(half3(_565) + _616);
    half _941 = clamp(dot(_1164, _616), half(0.0), half(1.0));
    half3 _1041 = cross(_1164, _1014);
    half _1044 = clamp(dot(_1164, _1014), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1061 = max(mix((half(2.0) * _941) * _794, _941 + _794, half(params.facet_alpha)), half(0.000244140625));
    half _1068 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1044, _1044, dot(_1041, _1041)) * (half(6433.98193359375) * _1061));
    half3 _1080 = fma(clamp(half4(_689).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_883).xyz * (mix(half4(_857).xxx, half4(_857).yyy, half3(float3(0.039999999105930328369140625))) * _876)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1068 * (_1068 * (half(6.283185482025146484375) * _1061)), half(65504.0))) * _876) * (half4(frame.lightColor).xyz * _941), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1080, half(1.0)));
    return out;
}

