#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    float3 _958 = fast::normalize(in.v_normal);
    float3 _964 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1268 = fast::max(dot(_958, _964), 9.9999997473787516355514526367188e-05);
    float3 _1272 = reflect(-_964, _958);
    float4 _1307 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1268, params.facet_perceptualRoughness), level(0.0));
    float3 _1326 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1307.y) - 1.0));
    float _1381 = 1.0 - _1268;
    float _1384 = _1381 * _1381;
    float _1391 = fma(0.959999978542327880859375, (_1384 * _1384) * _1381, 0.039999999105930328369140625);
    float _1396 = fast::clamp(params.coat, 0.0, 1.0);
    float _1363 = fma(-_1391, _1396, 1.0);
    float _1401 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1532 = fast::normalize(_964 + frame.lightDirection.xyz);
    float _1466 = fast::clamp(dot(_958, frame.lightDirection.xyz), 0.0, 1.0);
    float _1470 = fast::clamp(dot(_958, _1532), 0.0, 1.0);
    float _1474 = fast::clamp(dot(frame.lightDirection.xyz, _1532), 0.0, 1.0);
    float _1570 = 4096.0 * params.facet_alpha;
    float3 _1586 = cross(_958, _1532);
    float _1590 = _1586.x;
    float4 _1594 = float4(_1590, _1586.yz, params.facet_alpha * _1470) * 64.0;
    float _1576 = _1570 / dot(_1594, _1594);
    float _1605 = params.facet_alpha * params.facet_alpha;
    float _1611 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1615 = sqrt(fma(_1268 * _1268, _1611, _1605));
    float _1638 = 1.0 - _1474;
    float _1641 = _1638 * _1638;
    float _1646 = (_1641 * _1641) * _1638;
    float3 _1649 = float3(1.0) - float3(params.facet_f0);
    float3 _1492 = frame.lightColor.xyz * _1466;
    float _1685 = _1401 * _1401;
    float4 _1737 = float4(_1590, _1586.yz, _1685 * _1470) * 64.0;
    float _1695 = 12.56637096405029296875 * fast::max(_1474 * _1474, 6.103515625e-05);
    float _1697 = 4096.0 * _1685;
    float _1701 = _1697 / (dot(_1737, _1737) * _1695);
    float3 _1815 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1818 = dot(_1815, _1815);
    float3 _1823 = _1815 * rsqrt(fast::max(_1818, 9.9999999392252902907785028219223e-09));
    float _1827 = _1818 * float(frame.punctualLights[0].positionFalloff.w);
    float _1832 = fast::clamp(fma(-_1827, _1827, 1.0), 0.0, 1.0);
    float _1851 = fast::clamp(fma(dot(-_1823, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1983 = fast::normalize(_964 + _1823);
    float _1917 = fast::clamp(dot(_958, _1823), 0.0, 1.0);
    float _1921 = fast::clamp(dot(_958, _1983), 0.0, 1.0);
    float _1925 = fast::clamp(dot(_1823, _1983), 0.0, 1.0);
    float3 _2037 = cross(_958, _1983);
    float _2041 = _2037.x;
    float4 _2045 = float4(_2041, _2037.yz, params.facet_alpha * _1921) * 64.0;
    float _2027 = _1570 / dot(_2045, _2045);
    float _2089 = 1.0 - _1925;
    float _2092 = _2089 * _2089;
    float _2097 = (_2092 * _2092) * _2089;
    float3 _1943 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1832 * _1832) / fast::max(_1818, 9.9999997473787516355514526367188e-05)) * _1851) * _1851)) * _1917;
    float4 _2188 = float4(_2041, _2037.yz, _1685 * _1921) * 64.0;
    float _2146 = 12.56637096405029296875 * fast::max(_1925 * _1925, 6.103515625e-05);
    float _2152 = _1697 / (dot(_2188, _2188) * _2146);
    float3 _2266 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2269 = dot(_2266, _2266);
    float3 _2274 = _2266 * rsqrt(fast::max(_2269, 9.9999999392252902907785028219223e-09));
    float _2278 = _2269 * float(frame.punctualLights[1].positionFalloff.w);
    float _2283 = fast::clamp(fma(-_2278, _2278, 1.0), 0.0, 1.0);
    float _2302 = fast::clamp(fma(dot(-_2274, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2434 = fast::normalize(_964 + _2274);
    float _2368 = fast::clamp(dot(_958, _2274), 0.0, 1.0);
    float _2372 = fast::clamp(dot(_958, _2434), 0.0, 1.0);
    float _2376 = fast::clamp(dot(_2274, _2434), 0.0, 1.0);
    float3 _2488 = cross(_958, _2434);
    float _2492 = _2488.x;
    float4 _2496 = float4(_2492, _2488.yz, params.facet_alpha * _2372) * 64.0;
    float _2478 = _1570 / dot(_2496, _2496);
    float _2540 = 1.0 - _2376;
    float _2543 = _2540 * _2540;
    float _2548 = (_2543 * _2543) * _2540;
    float3 _2394 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2283 * _2283) / fast::max(_2269, 9.9999997473787516355514526367188e-05)) * _2302) * _2302)) * _2368;
    float4 _2639 = float4(_2492, _2488.yz, _1685 * _2372) * 64.0;
    float _2597 = 12.56637096405029296875 * fast::max(_2376 * _2376, 6.103515625e-05);
    float _2603 = _1697 / (dot(_2639, _2639) * _2597);
    float3 _2682 = ((mix(facet_environment.sample(facet_environmentSmplr, _1272, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1307.xxx, _1307.yyy, float3(params.facet_f0)) * _1326), facet_environment.sample(facet_environmentSmplr, _1272, level(_1401 * 4.0)).xyz, float3(_1391 * _1396)) + fast::min(fma(((float3(params.facet_f0) + (_1649 * _1646)) * (((_1576 * _1576) * 0.3183098733425140380859375) * (0.5 / fma(_1466, _1615, _1268 * sqrt(fma(_1466 * _1466, _1611, _1605)))))) * _1326, _1492 * _1363, _1492 * ((_1701 * (_1701 * _1695)) * (fma(0.959999978542327880859375, _1646, 0.039999999105930328369140625) * _1396))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1649 * _2097)) * (((_2027 * _2027) * 0.3183098733425140380859375) * (0.5 / fma(_1917, _1615, _1268 * sqrt(fma(_1917 * _1917, _1611, _1605)))))) * _1326, _1943 * _1363, _1943 * ((_2152 * (_2152 * _2146)) * (fma(0.959999978542327880859375, _2097, 0.039999999105930328369140625) * _1396))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1649 * _2548)) * (((_2478 * _2478) * 0.3183098733425140380859375) * (0.5 / fma(_2368, _1615, _1268 * sqrt(fma(_2368 * _2368, _1611, _1605)))))) * _1326, _2394 * _1363, _2394 * ((_2603 * (_2603 * _2597)) * (fma(0.959999978542327880859375, _2548, 0.039999999105930328369140625) * _1396))), float3(65504.0));
    out.fragColor = float4(_2682, 1.0);
    return out;
}

