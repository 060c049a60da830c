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
    float3 _698 = fast::normalize(in.v_toEye);
    float2 _842 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _845 = facet_material_albedo.sample(facet_material_albedoSmplr, _842);
    float4 _855 = facet_material_relief.sample(facet_material_reliefSmplr, _842);
    half3 _859 = (half4(_855).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _865 = fract(_842 * 4.0);
    float _867 = _865.x;
    float _874 = _865.y;
    half3 _1450;
    do
    {
        half3 _899 = half4(in.v_tangent).xyz;
        if (float(dot(_899, _899)) == 0.0)
        {
            _1450 = normalize(half3(in.v_normal));
            break;
        }
        _1450 = normalize(((_899 * _859.x) + ((cross(half3(in.v_normal), _899) * half(in.v_tangent.w)) * _859.y)) + (half3(in.v_normal) * _859.z));
        break;
    } while(false);
    half3 _942 = clamp(half4(_845).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _951 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_867, 1.0 - _867), fast::min(_874, 1.0 - _874))))), half(0.0), half(1.0));
    half _1044 = max(dot(_1450, half3(_698)), half(9.9999997473787516355514526367188e-05));
    float4 _1109 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1044, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1128 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1109).y) - half(1.0)));
    float4 _1138 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_698), _1450)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _761 = half4(frame.lightDirection).xyz;
    half3 _1275 = normalize(half3(_698) + _761);
    half _1202 = clamp(dot(_1450, _761), half(0.0), half(1.0));
    half4 _1344 = half4(cross(_1450, _1275), half(params.facet_alpha) * clamp(dot(_1450, _1275), half(0.0), half(1.0))) * half(64.0);
    half _1321 = half(6.283185482025146484375) * max(mix((half(2.0) * _1202) * _1044, _1202 + _1044, half(params.facet_alpha)), half(0.000244140625));
    half _1323 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1344, _1344) * _1321);
    half3 _1352 = (fma(_942 * half3(in.v_diffuseLight), max(half3(_951), ((((((_942 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _951) + ((_942 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _951) + ((_942 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _951), _942 * half3(in.v_directDiffuse)) + ((half4(_1138).xyz * (mix(half4(_1109).xxx, half4(_1109).yyy, half3(float3(0.039999999105930328369140625))) * _1128)) * _951)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1323 * (_1323 * _1321), half(65504.0))) * _1128) * (half4(frame.lightColor).xyz * _1202), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1352, half(1.0)));
    return out;
}

