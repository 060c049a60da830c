#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    float3 _903 = fast::normalize(in.v_normal);
    float3 _907 = fast::normalize(in.v_toEye);
    float _1037 = _903.y;
    float _1042 = _903.z;
    float _1047 = _903.x;
    float _1165 = fast::max(dot(_903, _907), 9.9999997473787516355514526367188e-05);
    float3 _1169 = reflect(-_907, _903);
    float4 _1204 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1165, params.facet_perceptualRoughness), level(0.0));
    float3 _1223 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1204.y) - 1.0));
    float _1303 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1263 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1165, _1303), level(0.0));
    float3 _1310 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1276 = _1263.z;
    float _1278 = fma(-fast::max(_1310.x, fast::max(_1310.y, _1310.z)), _1276, 1.0);
    float3 _1296 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1037)) + (frame.sh[2].xyz * _1042)) + (frame.sh[3].xyz * _1047)) + (((((frame.sh[4].xyz * (_1047 * _1037)) + (frame.sh[5].xyz * (_1037 * _1042))) + (frame.sh[6].xyz * fma(3.0 * _1042, _1042, -1.0))) + (frame.sh[7].xyz * (_1047 * _1042))) + (frame.sh[8].xyz * fma(_1047, _1047, -(_1037 * _1037)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1169, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1204.xxx, _1204.yyy, float3(params.facet_f0)) * _1223)) * _1278;
    float3 _1456 = fast::normalize(_907 + frame.lightDirection.xyz);
    float _1398 = fast::clamp(dot(_903, frame.lightDirection.xyz), 0.0, 1.0);
    float _1402 = fast::clamp(dot(_903, _1456), 0.0, 1.0);
    float3 _1494 = cross(_903, _1456);
    float _1497 = _1402 * params.facet_alpha;
    float _1506 = params.facet_alpha / fma(_1497, _1497, dot(_1494, _1494));
    float _1519 = params.facet_alpha * params.facet_alpha;
    float _1525 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1552 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1456), 0.0, 1.0);
    float _1555 = _1552 * _1552;
    float _1633 = _1303 * _1303;
    float _1653 = 8192.0 * fma(-_1398, _1165, _1398 + _1165);
    float _1657 = 1.0 / (_1633 * _1653);
    float3 _1698 = fma(facet_environment.sample(facet_environmentSmplr, _1169, level(_1303 * 4.0)).xyz, _1310 * _1276, _1296) + (fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1555 * _1555) * _1552))) * (((_1506 * _1506) * 0.3183098733425140380859375) * (0.5 / fma(_1398, sqrt(fma(_1165 * _1165, _1525, _1519)), _1165 * sqrt(fma(_1398 * _1398, _1525, _1519))))), _1223, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * ((frame.lightColor.xyz * _1398) * _1278), float3(65504.0)) + fast::min((_1310 * ((((fma(_1657, _1653, 2.0) * pow(fast::max(fma(-_1402, _1402, 1.0), 0.0), 0.5 * (_1657 * _1653))) * 0.15915493667125701904296875) * (_1398 * (_1657 * (2048.0 * _1633)))) * _1263.w)) * frame.lightColor.xyz, float3(65504.0)));
    out.fragColor = float4(_1698, 1.0);
    return out;
}

