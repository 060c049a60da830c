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
    float3 _975 = fast::normalize(in.v_normal);
    float3 _981 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1127 = _975.y;
    float _1132 = _975.z;
    float _1137 = _975.x;
    float _1255 = fast::max(dot(_975, _981), 9.9999997473787516355514526367188e-05);
    float3 _1259 = reflect(-_981, _975);
    float4 _1294 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, params.facet_perceptualRoughness), level(0.0));
    float3 _1313 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1294.y) - 1.0));
    float _1400 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1357 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, _1400), level(0.0));
    float3 _1407 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1370 = _1357.z;
    float _1372 = fma(-fast::max(_1407.x, fast::max(_1407.y, _1407.z)), _1370, 1.0);
    float _1416 = _1400 * _1400;
    float _1377 = _1357.w;
    float3 _1393 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1127)) + (frame.sh[2].xyz * _1132)) + (frame.sh[3].xyz * _1137)) + (((((frame.sh[4].xyz * (_1137 * _1127)) + (frame.sh[5].xyz * (_1127 * _1132))) + (frame.sh[6].xyz * fma(3.0 * _1132, _1132, -1.0))) + (frame.sh[7].xyz * (_1137 * _1132))) + (frame.sh[8].xyz * fma(_1137, _1137, -(_1127 * _1127)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1259, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1294.xxx, _1294.yyy, float3(params.facet_f0)) * _1313)) * _1372;
    float3 _1467 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1470 = dot(_1467, _1467);
    float3 _1475 = _1467 * rsqrt(fast::max(_1470, 9.9999999392252902907785028219223e-09));
    float _1479 = _1470 * float(frame.punctualLights[0].positionFalloff.w);
    float _1484 = fast::clamp(fma(-_1479, _1479, 1.0), 0.0, 1.0);
    float _1503 = fast::clamp(fma(dot(-_1475, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1512 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1484 * _1484) / fast::max(_1470, 9.9999997473787516355514526367188e-05)) * _1503) * _1503);
    float3 _1635 = fast::normalize(_981 + _1475);
    float _1568 = fast::clamp(dot(_975, _1475), 0.0, 1.0);
    float _1572 = fast::clamp(dot(_975, _1635), 0.0, 1.0);
    float _1673 = 4096.0 * params.facet_alpha;
    float4 _1697 = float4(cross(_975, _1635), params.facet_alpha * _1572) * 64.0;
    float _1679 = _1673 / dot(_1697, _1697);
    float _1708 = params.facet_alpha * params.facet_alpha;
    float _1714 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1718 = sqrt(fma(_1255 * _1255, _1714, _1708));
    float _1741 = 1.0 - fast::clamp(dot(_1475, _1635), 0.0, 1.0);
    float _1744 = _1741 * _1741;
    float3 _1752 = float3(1.0) - float3(params.facet_f0);
    float _1785 = 8192.0 * fma(-_1568, _1255, _1568 + _1255);
    float _1789 = 1.0 / (_1416 * _1785);
    float _1796 = 2048.0 * _1416;
    float3 _1609 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1859 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1862 = dot(_1859, _1859);
    float3 _1867 = _1859 * rsqrt(fast::max(_1862, 9.9999999392252902907785028219223e-09));
    float _1871 = _1862 * float(frame.punctualLights[1].positionFalloff.w);
    float _1876 = fast::clamp(fma(-_1871, _1871, 1.0), 0.0, 1.0);
    float _1895 = fast::clamp(fma(dot(-_1867, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1904 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1876 * _1876) / fast::max(_1862, 9.9999997473787516355514526367188e-05)) * _1895) * _1895);
    float3 _2027 = fast::normalize(_981 + _1867);
    float _1960 = fast::clamp(dot(_975, _1867), 0.0, 1.0);
    float _1964 = fast::clamp(dot(_975, _2027), 0.0, 1.0);
    float4 _2089 = float4(cross(_975, _2027), params.facet_alpha * _1964) * 64.0;
    float _2071 = _1673 / dot(_2089, _2089);
    float _2133 = 1.0 - fast::clamp(dot(_1867, _2027), 0.0, 1.0);
    float _2136 = _2133 * _2133;
    float _2177 = 8192.0 * fma(-_1960, _1255, _1960 + _1255);
    float _2181 = 1.0 / (_1416 * _2177);
    float3 _2216 = (fma(facet_environment.sample(facet_environmentSmplr, _1259, level(_1400 * (4.0 * (2.0 - _1400)))).xyz, _1407 * _1370, _1393) + fast::min(fma(fma((float3(params.facet_f0) + (_1752 * ((_1744 * _1744) * _1741))) * (((_1679 * _1679) * 0.3183098733425140380859375) * (0.5 / fma(_1568, _1718, _1255 * sqrt(fma(_1568 * _1568, _1714, _1708))))), _1313, _1609), (_1512 * _1568) * _1372, (_1407 * ((((fma(_1789, _1785, 2.0) * pow(fast::max(fma(-_1572, _1572, 1.0), 0.0), 0.5 * (_1789 * _1785))) * 0.15915493667125701904296875) * (_1568 * (_1789 * _1796))) * _1377)) * _1512), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1752 * ((_2136 * _2136) * _2133))) * (((_2071 * _2071) * 0.3183098733425140380859375) * (0.5 / fma(_1960, _1718, _1255 * sqrt(fma(_1960 * _1960, _1714, _1708))))), _1313, _1609), (_1904 * _1960) * _1372, (_1407 * ((((fma(_2181, _2177, 2.0) * pow(fast::max(fma(-_1964, _1964, 1.0), 0.0), 0.5 * (_2181 * _2177))) * 0.15915493667125701904296875) * (_1960 * (_2181 * _1796))) * _1377)) * _1904), float3(65504.0));
    out.fragColor = float4(_2216, 1.0);
    return out;
}

