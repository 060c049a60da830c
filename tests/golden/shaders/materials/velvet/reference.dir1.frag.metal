#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _538 = fast::normalize(in.v_normal);
    float3 _542 = fast::normalize(in.v_toEye);
    float _662 = _538.y;
    float _667 = _538.z;
    float _672 = _538.x;
    float _780 = fast::max(dot(_538, _542), 9.9999997473787516355514526367188e-05);
    float4 _785 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_780, params.facet_perceptualRoughness), level(0.0));
    float3 _831 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _798 = _785.z;
    float _800 = fma(-fast::max(_831.x, fast::max(_831.y, _831.z)), _798, 1.0);
    float _865 = dot(_538, frame.lightDirection.xyz);
    float _867 = fast::clamp(_865, 0.0, 1.0);
    float _881 = fast::clamp(dot(_538, fast::normalize(_542 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _952 = 8192.0 * fma(-_867, _780, _867 + _780);
    float _956 = 1.0 / (params.facet_alpha * _952);
    float3 _991 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_542, _538), level(params.facet_perceptualRoughness * 4.0)).xyz, _831 * _798, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _662)) + (frame.sh[2].xyz * _667)) + (frame.sh[3].xyz * _672)) + (((((frame.sh[4].xyz * (_672 * _662)) + (frame.sh[5].xyz * (_662 * _667))) + (frame.sh[6].xyz * fma(3.0 * _667, _667, -1.0))) + (frame.sh[7].xyz * (_672 * _667))) + (frame.sh[8].xyz * fma(_672, _672, -(_662 * _662)))), float3(0.0))) * _800) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_865 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_867), float3(0.0), float3(1.0))) * _800) + (_831 * ((((fma(_956, _952, 2.0) * pow(fast::max(fma(-_881, _881, 1.0), 0.0), 0.5 * (_956 * _952))) * 0.15915493667125701904296875) * (_867 * (_956 * (2048.0 * params.facet_alpha)))) * _785.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_991, 1.0);
    return out;
}

