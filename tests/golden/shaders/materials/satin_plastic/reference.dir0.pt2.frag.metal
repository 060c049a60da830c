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
    float3 _968 = fast::normalize(in.v_normal);
    float3 _974 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1121 = _968.y;
    float _1126 = _968.z;
    float _1131 = _968.x;
    float _1249 = fast::max(dot(_968, _974), 9.9999997473787516355514526367188e-05);
    float3 _1253 = reflect(-_974, _968);
    float4 _1288 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1249, params.facet_perceptualRoughness), level(0.0));
    float3 _1307 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1288.y) - 1.0));
    float4 _1349 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1249, params.facet_sheenRoughness), level(0.0));
    float _1362 = _1349.z;
    float _1364 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _1362, 1.0);
    float _1369 = _1349.w;
    float3 _1388 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1121)) + (frame.sh[2].xyz * _1126)) + (frame.sh[3].xyz * _1131)) + (((((frame.sh[4].xyz * (_1131 * _1121)) + (frame.sh[5].xyz * (_1121 * _1126))) + (frame.sh[6].xyz * fma(3.0 * _1126, _1126, -1.0))) + (frame.sh[7].xyz * (_1131 * _1126))) + (frame.sh[8].xyz * fma(_1131, _1131, -(_1121 * _1121)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1253, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1288.xxx, _1288.yyy, float3(params.facet_f0)) * _1307)) * _1364;
    float3 _1437 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1440 = dot(_1437, _1437);
    float3 _1445 = _1437 * rsqrt(fast::max(_1440, 9.9999999392252902907785028219223e-09));
    float _1449 = _1440 * float(frame.punctualLights[0].positionFalloff.w);
    float _1454 = fast::clamp(fma(-_1449, _1449, 1.0), 0.0, 1.0);
    float _1473 = fast::clamp(fma(dot(-_1445, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1482 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1454 * _1454) / fast::max(_1440, 9.9999997473787516355514526367188e-05)) * _1473) * _1473);
    float3 _1605 = fast::normalize(_974 + _1445);
    float _1538 = fast::clamp(dot(_968, _1445), 0.0, 1.0);
    float _1542 = fast::clamp(dot(_968, _1605), 0.0, 1.0);
    float _1643 = 4096.0 * params.facet_alpha;
    float4 _1667 = float4(cross(_968, _1605), params.facet_alpha * _1542) * 64.0;
    float _1649 = _1643 / dot(_1667, _1667);
    float _1678 = params.facet_alpha * params.facet_alpha;
    float _1684 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1688 = sqrt(fma(_1249 * _1249, _1684, _1678));
    float _1711 = 1.0 - fast::clamp(dot(_1445, _1605), 0.0, 1.0);
    float _1714 = _1711 * _1711;
    float3 _1722 = float3(1.0) - float3(params.facet_f0);
    float _1755 = 8192.0 * fma(-_1538, _1249, _1538 + _1249);
    float _1759 = 1.0 / (params.facet_sheenAlpha * _1755);
    float _1766 = 2048.0 * params.facet_sheenAlpha;
    float3 _1579 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1829 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1832 = dot(_1829, _1829);
    float3 _1837 = _1829 * rsqrt(fast::max(_1832, 9.9999999392252902907785028219223e-09));
    float _1841 = _1832 * float(frame.punctualLights[1].positionFalloff.w);
    float _1846 = fast::clamp(fma(-_1841, _1841, 1.0), 0.0, 1.0);
    float _1865 = fast::clamp(fma(dot(-_1837, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1874 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1846 * _1846) / fast::max(_1832, 9.9999997473787516355514526367188e-05)) * _1865) * _1865);
    float3 _1997 = fast::normalize(_974 + _1837);
    float _1930 = fast::clamp(dot(_968, _1837), 0.0, 1.0);
    float _1934 = fast::clamp(dot(_968, _1997), 0.0, 1.0);
    float4 _2059 = float4(cross(_968, _1997), params.facet_alpha * _1934) * 64.0;
    float _2041 = _1643 / dot(_2059, _2059);
    float _2103 = 1.0 - fast::clamp(dot(_1837, _1997), 0.0, 1.0);
    float _2106 = _2103 * _2103;
    float _2147 = 8192.0 * fma(-_1930, _1249, _1930 + _1249);
    float _2151 = 1.0 / (params.facet_sheenAlpha * _2147);
    float3 _2186 = (fma(facet_environment.sample(facet_environmentSmplr, _1253, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _1362, _1388) + fast::min(fma(fma((float3(params.facet_f0) + (_1722 * ((_1714 * _1714) * _1711))) * (((_1649 * _1649) * 0.3183098733425140380859375) * (0.5 / fma(_1538, _1688, _1249 * sqrt(fma(_1538 * _1538, _1684, _1678))))), _1307, _1579), (_1482 * _1538) * _1364, (float3(params.facet_sheenColor) * ((((fma(_1759, _1755, 2.0) * pow(fast::max(fma(-_1542, _1542, 1.0), 0.0), 0.5 * (_1759 * _1755))) * 0.15915493667125701904296875) * (_1538 * (_1759 * _1766))) * _1369)) * _1482), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1722 * ((_2106 * _2106) * _2103))) * (((_2041 * _2041) * 0.3183098733425140380859375) * (0.5 / fma(_1930, _1688, _1249 * sqrt(fma(_1930 * _1930, _1684, _1678))))), _1307, _1579), (_1874 * _1930) * _1364, (float3(params.facet_sheenColor) * ((((fma(_2151, _2147, 2.0) * pow(fast::max(fma(-_1934, _1934, 1.0), 0.0), 0.5 * (_2151 * _2147))) * 0.15915493667125701904296875) * (_1930 * (_2151 * _1766))) * _1369)) * _1874), float3(65504.0));
    out.fragColor = float4(_2186, 1.0);
    return out;
}

