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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    float3 _955 = fast::normalize(in.v_normal);
    float3 _961 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1129 = _955.y;
    float _1134 = _955.z;
    float _1139 = _955.x;
    float _1255 = fast::max(dot(_955, _961), 9.9999997473787516355514526367188e-05);
    float3 _1259 = reflect(-_961, _955);
    float4 _1297 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, params.facet_perceptualRoughness), level(0.0));
    float3 _1316 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1297.y) - 1.0));
    float4 _1347 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, params.facet_sheenRoughness), level(0.0));
    float _1360 = _1347.z;
    float _1362 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _1360, 1.0);
    float _1367 = _1347.w;
    float3 _1386 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1129)) + (frame.sh[2].xyz * _1134)) + (frame.sh[3].xyz * _1139)) + (((((frame.sh[4].xyz * (_1139 * _1129)) + (frame.sh[5].xyz * (_1129 * _1134))) + (frame.sh[6].xyz * fma(3.0 * _1134, _1134, -1.0))) + (frame.sh[7].xyz * (_1139 * _1134))) + (frame.sh[8].xyz * fma(_1139, _1139, -(_1129 * _1129)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1259, level(params.facet_environmentLod)).xyz * (mix(_1297.xxx, _1297.yyy, float3(params.facet_f0)) * _1316)) * _1362;
    float _1453 = fast::clamp(dot(_955, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1523 = fast::normalize(_961 + frame.lightDirection.xyz);
    float _1460 = fast::clamp(dot(_955, _1523), 0.0, 1.0);
    float _1561 = 4096.0 * params.facet_alpha;
    float4 _1585 = float4(cross(_955, _1523), params.facet_alpha * _1460) * 64.0;
    float _1567 = _1561 / dot(_1585, _1585);
    float _1596 = params.facet_alpha * params.facet_alpha;
    float _1602 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1606 = sqrt(fma(_1255 * _1255, _1602, _1596));
    float _1629 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1523), 0.0, 1.0);
    float _1632 = _1629 * _1629;
    float3 _1640 = float3(1.0) - float3(params.facet_f0);
    float _1673 = 8192.0 * fma(-_1453, _1255, _1453 + _1255);
    float _1677 = 1.0 / (params.facet_sheenAlpha * _1673);
    float _1684 = 2048.0 * params.facet_sheenAlpha;
    float3 _1497 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1747 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1750 = dot(_1747, _1747);
    float3 _1755 = _1747 * rsqrt(fast::max(_1750, 9.9999999392252902907785028219223e-09));
    float _1759 = _1750 * float(frame.punctualLights[0].positionFalloff.w);
    float _1764 = fast::clamp(fma(-_1759, _1759, 1.0), 0.0, 1.0);
    float _1783 = fast::clamp(fma(dot(-_1755, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1792 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1764 * _1764) / fast::max(_1750, 9.9999997473787516355514526367188e-05)) * _1783) * _1783);
    float _1845 = fast::clamp(dot(_955, _1755), 0.0, 1.0);
    float3 _1915 = fast::normalize(_961 + _1755);
    float _1852 = fast::clamp(dot(_955, _1915), 0.0, 1.0);
    float4 _1977 = float4(cross(_955, _1915), params.facet_alpha * _1852) * 64.0;
    float _1959 = _1561 / dot(_1977, _1977);
    float _2021 = 1.0 - fast::clamp(dot(_1755, _1915), 0.0, 1.0);
    float _2024 = _2021 * _2021;
    float _2065 = 8192.0 * fma(-_1845, _1255, _1845 + _1255);
    float _2069 = 1.0 / (params.facet_sheenAlpha * _2065);
    float3 _2104 = (fma(facet_environment.sample(facet_environmentSmplr, _1259, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _1360, _1386) + fast::min(fma(fma((float3(params.facet_f0) + (_1640 * ((_1632 * _1632) * _1629))) * (((_1567 * _1567) * 0.3183098733425140380859375) * (0.5 / fma(_1453, _1606, _1255 * sqrt(fma(_1453 * _1453, _1602, _1596))))), _1316, _1497), (frame.lightColor.xyz * _1453) * _1362, (float3(params.facet_sheenColor) * ((((fma(_1677, _1673, 2.0) * pow(fast::max(fma(-_1460, _1460, 1.0), 0.0), 0.5 * (_1677 * _1673))) * 0.15915493667125701904296875) * (_1453 * (_1677 * _1684))) * _1367)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1640 * ((_2024 * _2024) * _2021))) * (((_1959 * _1959) * 0.3183098733425140380859375) * (0.5 / fma(_1845, _1606, _1255 * sqrt(fma(_1845 * _1845, _1602, _1596))))), _1316, _1497), (_1792 * _1845) * _1362, (float3(params.facet_sheenColor) * ((((fma(_2069, _2065, 2.0) * pow(fast::max(fma(-_1852, _1852, 1.0), 0.0), 0.5 * (_2069 * _2065))) * 0.15915493667125701904296875) * (_1845 * (_2069 * _1684))) * _1367)) * _1792), float3(65504.0));
    float3 _2139 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2142 = dot(_2139, _2139);
    float3 _2147 = _2139 * rsqrt(fast::max(_2142, 9.9999999392252902907785028219223e-09));
    float _2151 = _2142 * float(frame.punctualLights[1].positionFalloff.w);
    float _2156 = fast::clamp(fma(-_2151, _2151, 1.0), 0.0, 1.0);
    float _2175 = fast::clamp(fma(dot(-_2147, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2184 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2156 * _2156) / fast::max(_2142, 9.9999997473787516355514526367188e-05)) * _2175) * _2175);
    float _2237 = fast::clamp(dot(_955, _2147), 0.0, 1.0);
    float3 _2307 = fast::normalize(_961 + _2147);
    float _2244 = fast::clamp(dot(_955, _2307), 0.0, 1.0);
    float4 _2369 = float4(cross(_955, _2307), params.facet_alpha * _2244) * 64.0;
    float _2351 = _1561 / dot(_2369, _2369);
    float _2413 = 1.0 - fast::clamp(dot(_2147, _2307), 0.0, 1.0);
    float _2416 = _2413 * _2413;
    float _2457 = 8192.0 * fma(-_2237, _1255, _2237 + _1255);
    float _2461 = 1.0 / (params.facet_sheenAlpha * _2457);
    out.fragColor = float4(_2104 + fast::min(fma(fma((float3(params.facet_f0) + (_1640 * ((_2416 * _2416) * _2413))) * (((_2351 * _2351) * 0.3183098733425140380859375) * (0.5 / fma(_2237, _1606, _1255 * sqrt(fma(_2237 * _2237, _1602, _1596))))), _1316, _1497), (_2184 * _2237) * _1362, (float3(params.facet_sheenColor) * ((((fma(_2461, _2457, 2.0) * pow(fast::max(fma(-_2244, _2244, 1.0), 0.0), 0.5 * (_2461 * _2457))) * 0.15915493667125701904296875) * (_2237 * (_2461 * _1684))) * _1367)) * _2184), float3(65504.0)), 1.0);
    return out;
}

