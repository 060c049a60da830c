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
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    half3 _656 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _684 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _688 = (half4(_684).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1131;
    do
    {
        half3 _701 = half4(in.v_tangent).xyz;
        if (float(dot(_701, _701)) == 0.0)
        {
            _1131 = normalize(half3(in.v_normal));
            break;
        }
        _1131 = normalize(((_701 * _688.x) + ((cross(half3(in.v_normal), _701) * half(in.v_tangent.w)) * _688.y)) + (half3(in.v_normal) * _688.z));
        break;
    } while(false);
    half _737 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _747 = dfdx(float3(_1131));
    float3 _749 = dfdy(float3(_1131));
    half _760 = _737 * _737;
    half _837 = clamp(half(sqrt(sqrt(fast::min(fma(float(_760), float(_760), fast::min((dot(_747, _747) + dot(_749, _749)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half3 _813 = reflect(-_656, _1131);
    float4 _844 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1131, _656), half(9.9999997473787516355514526367188e-05)), _837)), level(0.0));
    half3 _853 = mix(half4(_844).xxx, half4(_844).yyy, half3(float3(params.facet_f0)));
    float4 _863 = facet_environment.sample(facet_environmentSmplr, float3(_813), level(_837 * (half(4.0) * (half(2.0) - _837))));
    half3 _603 = half4(frame.lightDirection).xyz;
    half _1003 = clamp(dot(_813, _603), half(0.0), half(1.0));
    half _1006 = _1003 * _1003;
    half4 _1189 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1006 * _1006, _837), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1018 = _1189.x;
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_863).xyz * _853) + min((_853 * ((_1018 * _1018) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1131, _603), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

