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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _972 = fast::normalize(in.v_normal);
    float3 _978 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1145 = _972.y;
    float _1150 = _972.z;
    float _1155 = _972.x;
    float _1273 = fast::max(dot(_972, _978), 9.9999997473787516355514526367188e-05);
    float3 _1277 = reflect(-_978, _972);
    float4 _1312 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1273, params.facet_perceptualRoughness), level(0.0));
    float3 _1331 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1312.y) - 1.0));
    float _1415 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1372 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1273, _1415), level(0.0));
    float3 _1422 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1385 = _1372.z;
    float _1387 = fma(-fast::max(_1422.x, fast::max(_1422.y, _1422.z)), _1385, 1.0);
    float _1431 = _1415 * _1415;
    float _1392 = _1372.w;
    float3 _1408 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1145)) + (frame.sh[2].xyz * _1150)) + (frame.sh[3].xyz * _1155)) + (((((frame.sh[4].xyz * (_1155 * _1145)) + (frame.sh[5].xyz * (_1145 * _1150))) + (frame.sh[6].xyz * fma(3.0 * _1150, _1150, -1.0))) + (frame.sh[7].xyz * (_1155 * _1150))) + (frame.sh[8].xyz * fma(_1155, _1155, -(_1145 * _1145)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1277, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1312.xxx, _1312.yyy, float3(params.facet_f0)) * _1331)) * _1387;
    float3 _1567 = fast::normalize(_978 + frame.lightDirection.xyz);
    float _1500 = fast::clamp(dot(_972, frame.lightDirection.xyz), 0.0, 1.0);
    float _1504 = fast::clamp(dot(_972, _1567), 0.0, 1.0);
    float _1605 = 4096.0 * params.facet_alpha;
    float4 _1629 = float4(cross(_972, _1567), params.facet_alpha * _1504) * 64.0;
    float _1611 = _1605 / dot(_1629, _1629);
    float _1640 = params.facet_alpha * params.facet_alpha;
    float _1646 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1650 = sqrt(fma(_1273 * _1273, _1646, _1640));
    float _1673 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1567), 0.0, 1.0);
    float _1676 = _1673 * _1673;
    float3 _1684 = float3(1.0) - float3(params.facet_f0);
    float _1717 = 8192.0 * fma(-_1500, _1273, _1500 + _1273);
    float _1721 = 1.0 / (_1431 * _1717);
    float _1728 = 2048.0 * _1431;
    float3 _1541 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1791 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1794 = dot(_1791, _1791);
    float3 _1799 = _1791 * rsqrt(fast::max(_1794, 9.9999999392252902907785028219223e-09));
    float _1803 = _1794 * float(frame.punctualLights[0].positionFalloff.w);
    float _1808 = fast::clamp(fma(-_1803, _1803, 1.0), 0.0, 1.0);
    float _1827 = fast::clamp(fma(dot(-_1799, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1836 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1808 * _1808) / fast::max(_1794, 9.9999997473787516355514526367188e-05)) * _1827) * _1827);
    float3 _1959 = fast::normalize(_978 + _1799);
    float _1892 = fast::clamp(dot(_972, _1799), 0.0, 1.0);
    float _1896 = fast::clamp(dot(_972, _1959), 0.0, 1.0);
    float4 _2021 = float4(cross(_972, _1959), params.facet_alpha * _1896) * 64.0;
    float _2003 = _1605 / dot(_2021, _2021);
    float _2065 = 1.0 - fast::clamp(dot(_1799, _1959), 0.0, 1.0);
    float _2068 = _2065 * _2065;
    float _2109 = 8192.0 * fma(-_1892, _1273, _1892 + _1273);
    float _2113 = 1.0 / (_1431 * _2109);
    float3 _2148 = (fma(facet_environment.sample(facet_environmentSmplr, _1277, level(_1415 * 4.0)).xyz, _1422 * _1385, _1408) + fast::min(fma(fma((float3(params.facet_f0) + (_1684 * ((_1676 * _1676) * _1673))) * (((_1611 * _1611) * 0.3183098733425140380859375) * (0.5 / fma(_1500, _1650, _1273 * sqrt(fma(_1500 * _1500, _1646, _1640))))), _1331, _1541), (frame.lightColor.xyz * _1500) * _1387, (_1422 * ((((fma(_1721, _1717, 2.0) * pow(fast::max(fma(-_1504, _1504, 1.0), 0.0), 0.5 * (_1721 * _1717))) * 0.15915493667125701904296875) * (_1500 * (_1721 * _1728))) * _1392)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1684 * ((_2068 * _2068) * _2065))) * (((_2003 * _2003) * 0.3183098733425140380859375) * (0.5 / fma(_1892, _1650, _1273 * sqrt(fma(_1892 * _1892, _1646, _1640))))), _1331, _1541), (_1836 * _1892) * _1387, (_1422 * ((((fma(_2113, _2109, 2.0) * pow(fast::max(fma(-_1896, _1896, 1.0), 0.0), 0.5 * (_2113 * _2109))) * 0.15915493667125701904296875) * (_1892 * (_2113 * _1728))) * _1392)) * _1836), float3(65504.0));
    float3 _2183 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2186 = dot(_2183, _2183);
    float3 _2191 = _2183 * rsqrt(fast::max(_2186, 9.9999999392252902907785028219223e-09));
    float _2195 = _2186 * float(frame.punctualLights[1].positionFalloff.w);
    float _2200 = fast::clamp(fma(-_2195, _2195, 1.0), 0.0, 1.0);
    float _2219 = fast::clamp(fma(dot(-_2191, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2228 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2200 * _2200) / fast::max(_2186, 9.9999997473787516355514526367188e-05)) * _2219) * _2219);
    float3 _2351 = fast::normalize(_978 + _2191);
    float _2284 = fast::clamp(dot(_972, _2191), 0.0, 1.0);
    float _2288 = fast::clamp(dot(_972, _2351), 0.0, 1.0);
    float4 _2413 = float4(cross(_972, _2351), params.facet_alpha * _2288) * 64.0;
    float _2395 = _1605 / dot(_2413, _2413);
    float _2457 = 1.0 - fast::clamp(dot(_2191, _2351), 0.0, 1.0);
    float _2460 = _2457 * _2457;
    float _2501 = 8192.0 * fma(-_2284, _1273, _2284 + _1273);
    float _2505 = 1.0 / (_1431 * _2501);
    out.fragColor = float4(_2148 + fast::min(fma(fma((float3(params.facet_f0) + (_1684 * ((_2460 * _2460) * _2457))) * (((_2395 * _2395) * 0.3183098733425140380859375) * (0.5 / fma(_2284, _1650, _1273 * sqrt(fma(_2284 * _2284, _1646, _1640))))), _1331, _1541), (_2228 * _2284) * _1387, (_1422 * ((((fma(_2505, _2501, 2.0) * pow(fast::max(fma(-_2288, _2288, 1.0), 0.0), 0.5 * (_2505 * _2501))) * 0.15915493667125701904296875) * (_2284 * (_2505 * _1728))) * _1392)) * _2228), float3(65504.0)), 1.0);
    return out;
}

