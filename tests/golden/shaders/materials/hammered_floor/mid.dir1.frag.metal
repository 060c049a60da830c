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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    half3 _686 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _714 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _718 = (half4(_714).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1187;
    do
    {
        half3 _731 = half4(in.v_tangent).xyz;
        if (float(dot(_731, _731)) == 0.0)
        {
            _1187 = normalize(half3(in.v_normal));
            break;
        }
        _1187 = normalize(((_731 * _718.x) + ((cross(half3(in.v_normal), _731) * half(in.v_tangent.w)) * _718.y)) + (half3(in.v_normal) * _718.z));
        break;
    } while(false);
    half _767 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _777 = dfdx(float3(_1187));
    float3 _779 = dfdy(float3(_1187));
    half _790 = _767 * _767;
    half _866 = clamp(half(sqrt(sqrt(fast::min(fma(float(_790), float(_790), fast::min((dot(_777, _777) + dot(_779, _779)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _839 = max(dot(_1187, _686), half(9.9999997473787516355514526367188e-05));
    float4 _873 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_839, _866)), level(0.0));
    float4 _892 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_686, _1187)), level(_866 * (half(4.0) * (half(2.0) - _866))));
    half3 _636 = half4(frame.lightDirection).xyz;
    half _996 = _866 * _866;
    half _947 = clamp(dot(_1187, _636), half(0.0), half(1.0));
    half3 _1007 = normalize(_686 + _636);
    half4 _1076 = half4(cross(_1187, _1007), _996 * clamp(dot(_1187, _1007), half(0.0), half(1.0))) * half(64.0);
    half _1053 = half(6.283185482025146484375) * max(mix((half(2.0) * _947) * _839, _947 + _839, _996), half(0.000244140625));
    half _1055 = (half(4096.0) * _996) / (dot(_1076, _1076) * _1053);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_892).xyz * mix(half4(_873).xxx, half4(_873).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min(_1055 * (_1055 * _1053), half(65504.0))) * (half4(frame.lightColor).xyz * _947), half3(float3(65504.0))), half(1.0)));
    return out;
}

