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
    float3 _976 = fast::normalize(in.v_normal);
    float3 _982 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1149 = _976.y;
    float _1154 = _976.z;
    float _1159 = _976.x;
    float _1277 = fast::max(dot(_976, _982), 9.9999997473787516355514526367188e-05);
    float3 _1281 = reflect(-_982, _976);
    float4 _1316 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1277, params.facet_perceptualRoughness), level(0.0));
    float3 _1335 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1316.y) - 1.0));
    float _1419 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1376 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1277, _1419), level(0.0));
    float3 _1426 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1389 = _1376.z;
    float _1391 = fma(-fast::max(_1426.x, fast::max(_1426.y, _1426.z)), _1389, 1.0);
    float _1435 = _1419 * _1419;
    float _1396 = _1376.w;
    float3 _1412 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1149)) + (frame.sh[2].xyz * _1154)) + (frame.sh[3].xyz * _1159)) + (((((frame.sh[4].xyz * (_1159 * _1149)) + (frame.sh[5].xyz * (_1149 * _1154))) + (frame.sh[6].xyz * fma(3.0 * _1154, _1154, -1.0))) + (frame.sh[7].xyz * (_1159 * _1154))) + (frame.sh[8].xyz * fma(_1159, _1159, -(_1149 * _1149)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1281, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1316.xxx, _1316.yyy, float3(params.facet_f0)) * _1335)) * _1391;
    float3 _1571 = fast::normalize(_982 + frame.lightDirection.xyz);
    float _1504 = fast::clamp(dot(_976, frame.lightDirection.xyz), 0.0, 1.0);
    float _1508 = fast::clamp(dot(_976, _1571), 0.0, 1.0);
    float _1610 = 4096.0 * params.facet_alpha;
    float3 _1629 = cross(_976, _1571) * 64.0;
    float _1632 = 64.0 * params.facet_alpha;
    float _1633 = _1508 * _1632;
    float _1616 = _1610 / fma(_1633, _1633, dot(_1629, _1629));
    float _1648 = params.facet_alpha * params.facet_alpha;
    float _1654 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1658 = sqrt(fma(_1277 * _1277, _1654, _1648));
    float _1681 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1571), 0.0, 1.0);
    float _1684 = _1681 * _1681;
    float3 _1692 = float3(1.0) - float3(params.facet_f0);
    float _1725 = 8192.0 * fma(-_1504, _1277, _1504 + _1277);
    float _1729 = 1.0 / (_1435 * _1725);
    float _1736 = 2048.0 * _1435;
    float3 _1545 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1799 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1802 = dot(_1799, _1799);
    float3 _1807 = _1799 * rsqrt(fast::max(_1802, 9.9999999392252902907785028219223e-09));
    float _1811 = _1802 * float(frame.punctualLights[0].positionFalloff.w);
    float _1816 = fast::clamp(fma(-_1811, _1811, 1.0), 0.0, 1.0);
    float _1835 = fast::clamp(fma(dot(-_1807, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1844 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1816 * _1816) / fast::max(_1802, 9.9999997473787516355514526367188e-05)) * _1835) * _1835);
    float3 _1967 = fast::normalize(_982 + _1807);
    float _1900 = fast::clamp(dot(_976, _1807), 0.0, 1.0);
    float _1904 = fast::clamp(dot(_976, _1967), 0.0, 1.0);
    float3 _2025 = cross(_976, _1967) * 64.0;
    float _2029 = _1904 * _1632;
    float _2012 = _1610 / fma(_2029, _2029, dot(_2025, _2025));
    float _2077 = 1.0 - fast::clamp(dot(_1807, _1967), 0.0, 1.0);
    float _2080 = _2077 * _2077;
    float _2121 = 8192.0 * fma(-_1900, _1277, _1900 + _1277);
    float _2125 = 1.0 / (_1435 * _2121);
    float3 _2160 = (fma(facet_environment.sample(facet_environmentSmplr, _1281, level(_1419 * 4.0)).xyz, _1426 * _1389, _1412) + fast::min(fma(fma((float3(params.facet_f0) + (_1692 * ((_1684 * _1684) * _1681))) * (((_1616 * _1616) * 0.3183098733425140380859375) * (0.5 / fma(_1504, _1658, _1277 * sqrt(fma(_1504 * _1504, _1654, _1648))))), _1335, _1545), (frame.lightColor.xyz * _1504) * _1391, (_1426 * ((((fma(_1729, _1725, 2.0) * pow(fast::max(fma(-_1508, _1508, 1.0), 0.0), 0.5 * (_1729 * _1725))) * 0.15915493667125701904296875) * (_1504 * (_1729 * _1736))) * _1396)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1692 * ((_2080 * _2080) * _2077))) * (((_2012 * _2012) * 0.3183098733425140380859375) * (0.5 / fma(_1900, _1658, _1277 * sqrt(fma(_1900 * _1900, _1654, _1648))))), _1335, _1545), (_1844 * _1900) * _1391, (_1426 * ((((fma(_2125, _2121, 2.0) * pow(fast::max(fma(-_1904, _1904, 1.0), 0.0), 0.5 * (_2125 * _2121))) * 0.15915493667125701904296875) * (_1900 * (_2125 * _1736))) * _1396)) * _1844), float3(65504.0));
    float3 _2195 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2198 = dot(_2195, _2195);
    float3 _2203 = _2195 * rsqrt(fast::max(_2198, 9.9999999392252902907785028219223e-09));
    float _2207 = _2198 * float(frame.punctualLights[1].positionFalloff.w);
    float _2212 = fast::clamp(fma(-_2207, _2207, 1.0), 0.0, 1.0);
    float _2231 = fast::clamp(fma(dot(-_2203, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2240 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2212 * _2212) / fast::max(_2198, 9.9999997473787516355514526367188e-05)) * _2231) * _2231);
    float3 _2363 = fast::normalize(_982 + _2203);
    float _2296 = fast::clamp(dot(_976, _2203), 0.0, 1.0);
    float _2300 = fast::clamp(dot(_976, _2363), 0.0, 1.0);
    float3 _2421 = cross(_976, _2363) * 64.0;
    float _2425 = _2300 * _1632;
    float _2408 = _1610 / fma(_2425, _2425, dot(_2421, _2421));
    float _2473 = 1.0 - fast::clamp(dot(_2203, _2363), 0.0, 1.0);
    float _2476 = _2473 * _2473;
    float _2517 = 8192.0 * fma(-_2296, _1277, _2296 + _1277);
    float _2521 = 1.0 / (_1435 * _2517);
    out.fragColor = float4(_2160 + fast::min(fma(fma((float3(params.facet_f0) + (_1692 * ((_2476 * _2476) * _2473))) * (((_2408 * _2408) * 0.3183098733425140380859375) * (0.5 / fma(_2296, _1658, _1277 * sqrt(fma(_2296 * _2296, _1654, _1648))))), _1335, _1545), (_2240 * _2296) * _1391, (_1426 * ((((fma(_2521, _2517, 2.0) * pow(fast::max(fma(-_2300, _2300, 1.0), 0.0), 0.5 * (_2521 * _2517))) * 0.15915493667125701904296875) * (_2296 * (_2521 * _1736))) * _1396)) * _2240), float3(65504.0)), 1.0);
    return out;
}

