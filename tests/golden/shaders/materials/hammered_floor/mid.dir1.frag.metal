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
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _563 = fast::normalize(in.v_toEye);
    float4 _690 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _694 = (half4(_690).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1163;
    do
    {
        half3 _707 = half4(in.v_tangent).xyz;
        if (float(dot(_707, _707)) == 0.0)
        {
            _1163 = normalize(half3(in.v_normal));
            break;
        }
        _1163 = normalize(((_707 * _694.x) + ((cross(half3(in.v_normal), _707) * half(in.v_tangent.w)) * _694.y)) + (half3(in.v_normal) * _694.z));
        break;
    } while(false);
    half _743 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _753 = dfdx(float3(_1163));
    float3 _755 = dfdy(float3(_1163));
    half _766 = _743 * _743;
    half _842 = clamp(half(sqrt(sqrt(fast::min(fma(float(_766), float(_766), fast::min((dot(_753, _753) + dot(_755, _755)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _815 = max(dot(_1163, half3(_563)), half(9.9999997473787516355514526367188e-05));
    float4 _849 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_815, _842)), level(0.0));
    float4 _868 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_563), _1163)), level(_842 * (half(4.0) * (half(2.0) - _842))));
    half3 _622 = half4(frame.lightDirection).xyz;
    half _972 = _842 * _842;
    half3 _983 = normalize(half3(_563) + _622);
    half _926 = clamp(dot(_1163, _622), half(0.0), half(1.0));
    half4 _1052 = half4(cross(_1163, _983), _972 * clamp(dot(_1163, _983), half(0.0), half(1.0))) * half(64.0);
    half _1029 = half(6.283185482025146484375) * max(mix((half(2.0) * _926) * _815, _926 + _815, _972), half(0.000244140625));
    half _1031 = (half(4096.0) * _972) / (dot(_1052, _1052) * _1029);
    half3 _1060 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_868).xyz * mix(half4(_849).xxx, half4(_849).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min(_1031 * (_1031 * _1029), half(65504.0))) * (half4(frame.lightColor).xyz * _926), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1060, half(1.0)));
    return out;
}

