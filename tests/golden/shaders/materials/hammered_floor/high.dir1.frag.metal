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
    float3 _622 = fast::normalize(in.v_toEye);
    float4 _749 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _753 = (half4(_749).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1275;
    do
    {
        half3 _766 = half4(in.v_tangent).xyz;
        if (float(dot(_766, _766)) == 0.0)
        {
            _1275 = normalize(half3(in.v_normal));
            break;
        }
        _1275 = normalize(((_766 * _753.x) + ((cross(half3(in.v_normal), _766) * half(in.v_tangent.w)) * _753.y)) + (half3(in.v_normal) * _753.z));
        break;
    } while(false);
    half _802 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _812 = dfdx(float3(_1275));
    float3 _814 = dfdy(float3(_1275));
    half _825 = _802 * _802;
    half _901 = clamp(half(sqrt(sqrt(fast::min(fma(float(_825), float(_825), fast::min((dot(_812, _812) + dot(_814, _814)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _874 = max(dot(_1275, half3(_622)), half(9.9999997473787516355514526367188e-05));
    float4 _908 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_874, _901)), level(0.0));
    float4 _927 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_622), _1275)), level(_901 * (half(4.0) * (half(2.0) - _901))));
    half _1031 = _901 * _901;
    float3 _1043 = fast::normalize(_622 + frame.lightDirection.xyz);
    half _985 = clamp(dot(_1275, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1108 = half4(cross(_1275, half3(_1043)), _1031 * clamp(dot(_1275, half3(_1043)), half(0.0), half(1.0))) * half(64.0);
    half _1089 = (half(4096.0) * _1031) / dot(_1108, _1108);
    half _1119 = _1031 * _1031;
    half _1125 = fma(half(-float(_1031)), _1031, half(1.0));
    half _1153 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1043)), half(0.0), half(1.0));
    half _1156 = _1153 * _1153;
    half3 _1172 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_927).xyz * mix(half4(_908).xxx, half4(_908).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1156 * _1156) * _1153))) * min(min((_1089 * _1089) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_985, sqrt(fma(_874 * _874, _1125, _1119)), _874 * sqrt(fma(_985 * _985, _1125, _1119))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _985), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1172, half(1.0)));
    return out;
}

