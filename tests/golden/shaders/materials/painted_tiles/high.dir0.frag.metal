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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _652 = fast::normalize(in.v_toEye);
    float2 _752 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _755 = facet_material_albedo.sample(facet_material_albedoSmplr, _752);
    float4 _765 = facet_material_relief.sample(facet_material_reliefSmplr, _752);
    half3 _769 = (half4(_765).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _775 = fract(_752 * 4.0);
    float _777 = _775.x;
    float _784 = _775.y;
    half3 _1291;
    do
    {
        half3 _809 = half4(in.v_tangent).xyz;
        if (float(dot(_809, _809)) == 0.0)
        {
            _1291 = normalize(half3(in.v_normal));
            break;
        }
        _1291 = normalize(((_809 * _769.x) + ((cross(half3(in.v_normal), _809) * half(in.v_tangent.w)) * _769.y)) + (half3(in.v_normal) * _769.z));
        break;
    } while(false);
    half3 _946 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1291.y)) + (half4(frame.sh[2]).xyz * _1291.z)) + (half4(frame.sh[3]).xyz * _1291.x)) + (((((half4(frame.sh[4]).xyz * (_1291.x * _1291.y)) + (half4(frame.sh[5]).xyz * (_1291.y * _1291.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1291.z, _1291.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1291.x * _1291.z))) + (half4(frame.sh[8]).xyz * fma(_1291.x, _1291.x, half(-float(_1291.y * _1291.y))))), half3(float3(0.0)));
    half3 _969 = clamp(half4(_755).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _978 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_777, 1.0 - _777), fast::min(_784, 1.0 - _784))))), half(0.0), half(1.0));
    half _1059 = max(dot(_1291, half3(_652)), half(9.9999997473787516355514526367188e-05));
    float4 _1124 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1059, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1150 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_652), _1291)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1191 = fma(_969 * _946, max(half3(_978), ((((((_969 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _978) + ((_969 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _978) + ((_969 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _978), (half4(_1150).xyz * (mix(half4(_1124).xxx, half4(_1124).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1124).y) - half(1.0)))))) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1059 + _978)) - half(1.0)) + _978, half(0.0), half(1.0)));
    out.fragColor = float4(half4(_1191, half(1.0)));
    return out;
}

