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
    float3 _665 = fast::normalize(in.v_toEye);
    float2 _812 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _815 = facet_material_albedo.sample(facet_material_albedoSmplr, _812);
    float4 _825 = facet_material_relief.sample(facet_material_reliefSmplr, _812);
    half3 _829 = (half4(_825).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _835 = fract(_812 * 4.0);
    float _837 = _835.x;
    float _844 = _835.y;
    half3 _1386;
    do
    {
        half3 _869 = half4(in.v_tangent).xyz;
        if (float(dot(_869, _869)) == 0.0)
        {
            _1386 = normalize(half3(in.v_normal));
            break;
        }
        _1386 = normalize(((_869 * _829.x) + ((cross(half3(in.v_normal), _869) * half(in.v_tangent.w)) * _829.y)) + (half3(in.v_normal) * _829.z));
        break;
    } while(false);
    half3 _912 = clamp(half4(_815).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _921 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_837, 1.0 - _837), fast::min(_844, 1.0 - _844))))), half(0.0), half(1.0));
    half3 _1018 = reflect(-half3(_665), _1386);
    float4 _1080 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1386, half3(_665)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1111 = facet_environment.sample(facet_environmentSmplr, float3(_1018), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1033 = mix(half4(_1080).xxx, half4(_1080).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1080).y) - half(1.0))));
    half3 _728 = half4(frame.lightDirection).xyz;
    half _1270 = clamp(dot(_1018, _728), half(0.0), half(1.0));
    half _1273 = _1270 * _1270;
    half4 _1464 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1273 * _1273, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1285 = _1464.x;
    out.fragColor = float4(half4((fma(_912 * half3(in.v_diffuseLight), max(half3(_921), ((((((_912 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _921) + ((_912 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _921) + ((_912 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _921), _912 * half3(in.v_directDiffuse)) + ((half4(_1111).xyz * _1033) * _921)) + min((_1033 * ((_1285 * _1285) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1386, _728), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

