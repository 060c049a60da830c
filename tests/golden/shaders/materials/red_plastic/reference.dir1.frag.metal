#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _673 = fast::normalize(in.v_normal);
    float3 _677 = fast::normalize(in.v_toEye);
    float _795 = _673.y;
    float _800 = _673.z;
    float _805 = _673.x;
    float _923 = fast::max(dot(_673, _677), 9.9999997473787516355514526367188e-05);
    float4 _962 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_923, params.facet_perceptualRoughness), level(0.0));
    float3 _981 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _962.y) - 1.0));
    float3 _1103 = fast::normalize(_677 + frame.lightDirection.xyz);
    float _1048 = fast::clamp(dot(_673, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1165 = float4(cross(_673, _1103), params.facet_alpha * fast::clamp(dot(_673, _1103), 0.0, 1.0)) * 64.0;
    float _1147 = (4096.0 * params.facet_alpha) / dot(_1165, _1165);
    float _1176 = params.facet_alpha * params.facet_alpha;
    float _1182 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1209 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1103), 0.0, 1.0);
    float _1212 = _1209 * _1209;
    float3 _1234 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _795)) + (frame.sh[2].xyz * _800)) + (frame.sh[3].xyz * _805)) + (((((frame.sh[4].xyz * (_805 * _795)) + (frame.sh[5].xyz * (_795 * _800))) + (frame.sh[6].xyz * fma(3.0 * _800, _800, -1.0))) + (frame.sh[7].xyz * (_805 * _800))) + (frame.sh[8].xyz * fma(_805, _805, -(_795 * _795)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_677, _673), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_962.xxx, _962.yyy, float3(params.facet_f0)) * _981)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1212 * _1212) * _1209))) * (((_1147 * _1147) * 0.3183098733425140380859375) * (0.5 / fma(_1048, sqrt(fma(_923 * _923, _1182, _1176)), _923 * sqrt(fma(_1048 * _1048, _1182, _1176))))), _981, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1048), float3(65504.0));
    out.fragColor = float4(_1234, 1.0);
    return out;
}

