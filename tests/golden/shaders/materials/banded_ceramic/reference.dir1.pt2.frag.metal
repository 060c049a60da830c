#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    float3 _833 = fast::normalize(in.v_normal);
    float3 _839 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _982 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1031 = _833.y;
    float _1036 = _833.z;
    float _1041 = _833.x;
    float3 _1132 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_982)), float3(0.0), float3(1.0)) * 1.0;
    float _1207 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _982), 0.0, 1.0);
    float3 _1215 = float3((0.1599999964237213134765625 * _1207) * _1207);
    float _1224 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _982), 0.08900000154972076416015625, 1.0);
    float _1167 = fast::max(dot(_833, _839), 9.9999997473787516355514526367188e-05);
    float4 _1231 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1167, _1224), level(0.0));
    float3 _1250 = float3(1.0) + (_1215 * ((1.0 / _1231.y) - 1.0));
    float _1396 = _1224 * _1224;
    float3 _1407 = fast::normalize(_839 + frame.lightDirection.xyz);
    float _1317 = fast::clamp(dot(_833, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1445 = cross(_833, _1407);
    float _1448 = fast::clamp(dot(_833, _1407), 0.0, 1.0) * _1396;
    float _1457 = _1396 / fma(_1448, _1448, dot(_1445, _1445));
    float _1470 = _1396 * _1396;
    float _1476 = fma(-_1396, _1396, 1.0);
    float _1480 = sqrt(fma(_1167 * _1167, _1476, _1470));
    float _1503 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1407), 0.0, 1.0);
    float _1506 = _1503 * _1503;
    float3 _1514 = float3(1.0) - _1215;
    float3 _1348 = _1132 * 0.3183098733425140380859375;
    float3 _1536 = fma(_1132, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1031)) + (frame.sh[2].xyz * _1036)) + (frame.sh[3].xyz * _1041)) + (((((frame.sh[4].xyz * (_1041 * _1031)) + (frame.sh[5].xyz * (_1031 * _1036))) + (frame.sh[6].xyz * fma(3.0 * _1036, _1036, -1.0))) + (frame.sh[7].xyz * (_1041 * _1036))) + (frame.sh[8].xyz * fma(_1041, _1041, -(_1031 * _1031)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_839, _833), level(_1224 * 4.0)).xyz * (mix(_1231.xxx, _1231.yyy, _1215) * _1250)) + fast::min(fma((_1215 + (_1514 * ((_1506 * _1506) * _1503))) * (((_1457 * _1457) * 0.3183098733425140380859375) * (0.5 / fma(_1317, _1480, _1167 * sqrt(fma(_1317 * _1317, _1476, _1470))))), _1250, _1348) * (frame.lightColor.xyz * _1317), float3(65504.0));
    float3 _1571 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1574 = dot(_1571, _1571);
    float3 _1579 = _1571 * rsqrt(fast::max(_1574, 9.9999999392252902907785028219223e-09));
    float _1583 = _1574 * float(frame.punctualLights[0].positionFalloff.w);
    float _1588 = fast::clamp(fma(-_1583, _1583, 1.0), 0.0, 1.0);
    float _1607 = fast::clamp(fma(dot(-_1579, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1757 = fast::normalize(_839 + _1579);
    float _1667 = fast::clamp(dot(_833, _1579), 0.0, 1.0);
    float3 _1795 = cross(_833, _1757);
    float _1798 = fast::clamp(dot(_833, _1757), 0.0, 1.0) * _1396;
    float _1807 = _1396 / fma(_1798, _1798, dot(_1795, _1795));
    float _1853 = 1.0 - fast::clamp(dot(_1579, _1757), 0.0, 1.0);
    float _1856 = _1853 * _1853;
    float3 _1921 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1924 = dot(_1921, _1921);
    float3 _1929 = _1921 * rsqrt(fast::max(_1924, 9.9999999392252902907785028219223e-09));
    float _1933 = _1924 * float(frame.punctualLights[1].positionFalloff.w);
    float _1938 = fast::clamp(fma(-_1933, _1933, 1.0), 0.0, 1.0);
    float _1957 = fast::clamp(fma(dot(-_1929, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2107 = fast::normalize(_839 + _1929);
    float _2017 = fast::clamp(dot(_833, _1929), 0.0, 1.0);
    float3 _2145 = cross(_833, _2107);
    float _2148 = fast::clamp(dot(_833, _2107), 0.0, 1.0) * _1396;
    float _2157 = _1396 / fma(_2148, _2148, dot(_2145, _2145));
    float _2203 = 1.0 - fast::clamp(dot(_1929, _2107), 0.0, 1.0);
    float _2206 = _2203 * _2203;
    float3 _2236 = (_1536 + fast::min(fma((_1215 + (_1514 * ((_1856 * _1856) * _1853))) * (((_1807 * _1807) * 0.3183098733425140380859375) * (0.5 / fma(_1667, _1480, _1167 * sqrt(fma(_1667 * _1667, _1476, _1470))))), _1250, _1348) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1588 * _1588) / fast::max(_1574, 9.9999997473787516355514526367188e-05)) * _1607) * _1607)) * _1667), float3(65504.0))) + fast::min(fma((_1215 + (_1514 * ((_2206 * _2206) * _2203))) * (((_2157 * _2157) * 0.3183098733425140380859375) * (0.5 / fma(_2017, _1480, _1167 * sqrt(fma(_2017 * _2017, _1476, _1470))))), _1250, _1348) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1938 * _1938) / fast::max(_1924, 9.9999997473787516355514526367188e-05)) * _1957) * _1957)) * _2017), float3(65504.0));
    out.fragColor = float4(_2236, 1.0);
    return out;
}

