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
    float _1108 = _955.y;
    float _1113 = _955.z;
    float _1118 = _955.x;
    float _1234 = fast::max(dot(_955, _961), 9.9999997473787516355514526367188e-05);
    float3 _1238 = reflect(-_961, _955);
    float4 _1276 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1234, params.facet_perceptualRoughness), level(0.0));
    float3 _1295 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1276.y) - 1.0));
    float4 _1326 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1234, params.facet_sheenRoughness), level(0.0));
    float _1339 = _1326.z;
    float _1341 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _1339, 1.0);
    float _1346 = _1326.w;
    float3 _1365 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1108)) + (frame.sh[2].xyz * _1113)) + (frame.sh[3].xyz * _1118)) + (((((frame.sh[4].xyz * (_1118 * _1108)) + (frame.sh[5].xyz * (_1108 * _1113))) + (frame.sh[6].xyz * fma(3.0 * _1113, _1113, -1.0))) + (frame.sh[7].xyz * (_1118 * _1113))) + (frame.sh[8].xyz * fma(_1118, _1118, -(_1108 * _1108)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1238, level(params.facet_environmentLod)).xyz * (mix(_1276.xxx, _1276.yyy, float3(params.facet_f0)) * _1295)) * _1341;
    float3 _1414 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1417 = dot(_1414, _1414);
    float3 _1422 = _1414 * rsqrt(fast::max(_1417, 9.9999999392252902907785028219223e-09));
    float _1426 = _1417 * float(frame.punctualLights[0].positionFalloff.w);
    float _1431 = fast::clamp(fma(-_1426, _1426, 1.0), 0.0, 1.0);
    float _1450 = fast::clamp(fma(dot(-_1422, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1459 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1431 * _1431) / fast::max(_1417, 9.9999997473787516355514526367188e-05)) * _1450) * _1450);
    float _1512 = fast::clamp(dot(_955, _1422), 0.0, 1.0);
    float3 _1582 = fast::normalize(_961 + _1422);
    float _1519 = fast::clamp(dot(_955, _1582), 0.0, 1.0);
    float _1620 = 4096.0 * params.facet_alpha;
    float4 _1644 = float4(cross(_955, _1582), params.facet_alpha * _1519) * 64.0;
    float _1626 = _1620 / dot(_1644, _1644);
    float _1655 = params.facet_alpha * params.facet_alpha;
    float _1661 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1665 = sqrt(fma(_1234 * _1234, _1661, _1655));
    float _1688 = 1.0 - fast::clamp(dot(_1422, _1582), 0.0, 1.0);
    float _1691 = _1688 * _1688;
    float3 _1699 = float3(1.0) - float3(params.facet_f0);
    float _1732 = 8192.0 * fma(-_1512, _1234, _1512 + _1234);
    float _1736 = 1.0 / (params.facet_sheenAlpha * _1732);
    float _1743 = 2048.0 * params.facet_sheenAlpha;
    float3 _1556 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1806 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1809 = dot(_1806, _1806);
    float3 _1814 = _1806 * rsqrt(fast::max(_1809, 9.9999999392252902907785028219223e-09));
    float _1818 = _1809 * float(frame.punctualLights[1].positionFalloff.w);
    float _1823 = fast::clamp(fma(-_1818, _1818, 1.0), 0.0, 1.0);
    float _1842 = fast::clamp(fma(dot(-_1814, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1851 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1823 * _1823) / fast::max(_1809, 9.9999997473787516355514526367188e-05)) * _1842) * _1842);
    float _1904 = fast::clamp(dot(_955, _1814), 0.0, 1.0);
    float3 _1974 = fast::normalize(_961 + _1814);
    float _1911 = fast::clamp(dot(_955, _1974), 0.0, 1.0);
    float4 _2036 = float4(cross(_955, _1974), params.facet_alpha * _1911) * 64.0;
    float _2018 = _1620 / dot(_2036, _2036);
    float _2080 = 1.0 - fast::clamp(dot(_1814, _1974), 0.0, 1.0);
    float _2083 = _2080 * _2080;
    float _2124 = 8192.0 * fma(-_1904, _1234, _1904 + _1234);
    float _2128 = 1.0 / (params.facet_sheenAlpha * _2124);
    float3 _2163 = (fma(facet_environment.sample(facet_environmentSmplr, _1238, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _1339, _1365) + fast::min(fma(fma((float3(params.facet_f0) + (_1699 * ((_1691 * _1691) * _1688))) * (((_1626 * _1626) * 0.3183098733425140380859375) * (0.5 / fma(_1512, _1665, _1234 * sqrt(fma(_1512 * _1512, _1661, _1655))))), _1295, _1556), (_1459 * _1512) * _1341, (float3(params.facet_sheenColor) * ((((fma(_1736, _1732, 2.0) * pow(fast::max(fma(-_1519, _1519, 1.0), 0.0), 0.5 * (_1736 * _1732))) * 0.15915493667125701904296875) * (_1512 * (_1736 * _1743))) * _1346)) * _1459), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1699 * ((_2083 * _2083) * _2080))) * (((_2018 * _2018) * 0.3183098733425140380859375) * (0.5 / fma(_1904, _1665, _1234 * sqrt(fma(_1904 * _1904, _1661, _1655))))), _1295, _1556), (_1851 * _1904) * _1341, (float3(params.facet_sheenColor) * ((((fma(_2128, _2124, 2.0) * pow(fast::max(fma(-_1911, _1911, 1.0), 0.0), 0.5 * (_2128 * _2124))) * 0.15915493667125701904296875) * (_1904 * (_2128 * _1743))) * _1346)) * _1851), float3(65504.0));
    out.fragColor = float4(_2163, 1.0);
    return out;
}

