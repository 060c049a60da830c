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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_relief [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_reliefSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _501 = fast::normalize(in.v_toEye);
    float4 _594 = facet_material_relief.sample(facet_material_reliefSmplr, (in.v_uv0 * params.tiling));
    half3 _598 = (half4(_594).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1029;
    do
    {
        half3 _611 = half4(in.v_tangent).xyz;
        if (float(dot(_611, _611)) == 0.0)
        {
            _1029 = normalize(half3(in.v_normal));
            break;
        }
        _1029 = normalize(((_611 * _598.x) + ((cross(half3(in.v_normal), _611) * half(in.v_tangent.w)) * _598.y)) + (half3(in.v_normal) * _598.z));
        break;
    } while(false);
    half _647 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _656 = dfdx(float3(_1029));
    float3 _658 = dfdy(float3(_1029));
    half _669 = _647 * _647;
    half3 _786 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1029.y)) + (half4(frame.sh[2]).xyz * _1029.z)) + (half4(frame.sh[3]).xyz * _1029.x)) + (((((half4(frame.sh[4]).xyz * (_1029.x * _1029.y)) + (half4(frame.sh[5]).xyz * (_1029.y * _1029.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1029.z, _1029.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1029.x * _1029.z))) + (half4(frame.sh[8]).xyz * fma(_1029.x, _1029.x, half(-float(_1029.y * _1029.y))))), half3(float3(0.0)));
    half _869 = clamp(sqrt(sqrt(min(fma(_669, _669, min((dot(half3(_656), half3(_656)) + dot(half3(_658), half3(_658))) * half(0.300000011920928955078125), half(0.20000000298023223876953125))), half(1.0)))), half(0.08900000154972076416015625), half(1.0));
    float4 _876 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1029, half3(_501)), half(9.9999997473787516355514526367188e-05)), _869)), level(0.0));
    float4 _902 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_501), _1029)), level(_869 * half(4.0)));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), _786, half4(_902).xyz * (mix(half4(_876).xxx, half4(_876).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_876).y) - half(1.0)))))), half(1.0)));
    return out;
}

