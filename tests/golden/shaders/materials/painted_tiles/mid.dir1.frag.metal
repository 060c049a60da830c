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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    half3 _779 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _819 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _822 = facet_material_albedo.sample(facet_material_albedoSmplr, _819);
    float4 _832 = facet_material_relief.sample(facet_material_reliefSmplr, _819);
    half3 _836 = (half4(_832).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _842 = fract(_819 * 4.0);
    float _844 = _842.x;
    float _851 = _842.y;
    half3 _1384;
    do
    {
        half3 _876 = half4(in.v_tangent).xyz;
        if (float(dot(_876, _876)) == 0.0)
        {
            _1384 = normalize(half3(in.v_normal));
            break;
        }
        _1384 = normalize(((_876 * _836.x) + ((cross(half3(in.v_normal), _876) * half(in.v_tangent.w)) * _836.y)) + (half3(in.v_normal) * _836.z));
        break;
    } while(false);
    half3 _919 = clamp(half4(_822).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _928 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_844, 1.0 - _844), fast::min(_851, 1.0 - _851))))), half(0.0), half(1.0));
    half3 _1019 = reflect(-_779, _1384);
    half4 _1077 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _1079 = _1077.x;
    half2 _1097 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_1079 * _1079, exp2(half(-9.27999973297119140625) * max(dot(_1384, _779), half(9.9999997473787516355514526367188e-05)))), _1079, _1077.y)) + _1077.zw;
    half3 _1105 = (half3(float3(0.039999999105930328369140625)) * _1097.x) + half3(_1097.y);
    float4 _1028 = facet_environment.sample(facet_environmentSmplr, float3(_1019), level(params.facet_environmentLod));
    half3 _725 = half4(frame.lightDirection).xyz;
    half _1263 = clamp(dot(_1019, _725), half(0.0), half(1.0));
    half _1266 = _1263 * _1263;
    half4 _1453 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1266 * _1266, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1278 = _1453.x;
    out.fragColor = float4(half4((fma(_919 * half3(in.v_diffuseLight), max(half3(_928), ((((((_919 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _928) + ((_919 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _928) + ((_919 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _928), _919 * half3(in.v_directDiffuse)) + ((half4(_1028).xyz * _1105) * _928)) + min((_1105 * ((_1278 * _1278) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1384, _725), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

