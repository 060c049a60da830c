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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _774 = normalize(half3(in.v_normal));
    float3 _790 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _971 = max(dot(_774, half3(_790)), half(9.9999997473787516355514526367188e-05));
    half3 _975 = reflect(-half3(_790), _774);
    float4 _1010 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_971, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1029 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1010).y) - half(1.0)));
    float4 _1036 = facet_environment.sample(facet_environmentSmplr, float3(_975), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1113 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1070 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_971, _1113)), level(0.0));
    half3 _1120 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2219 = half4(_1070);
    half _1083 = _2219.z;
    half _1085 = fma(half(-float(max(_1120.x, max(_1120.y, _1120.z)))), _1083, half(1.0));
    half _1129 = _1113 * _1113;
    half4 _2223 = half4(_1070);
    half _1090 = _2223.w;
    float4 _1141 = facet_environment.sample(facet_environmentSmplr, float3(_975), level(_1113 * half(4.0)));
    half3 _836 = half4(frame.lightDirection).xyz;
    half3 _848 = half4(frame.lightColor).xyz;
    half3 _1257 = normalize(half3(_790) + _836);
    half _1196 = clamp(dot(_774, _836), half(0.0), half(1.0));
    half _1200 = clamp(dot(_774, _1257), half(0.0), half(1.0));
    half4 _1326 = half4(cross(_774, _1257), half(params.facet_alpha) * _1200) * half(64.0);
    half _1295 = _1196 + _971;
    half _1300 = half(4096.0) * half(params.facet_alpha);
    half _1303 = half(6.283185482025146484375) * max(mix((half(2.0) * _1196) * _971, _1295, half(params.facet_alpha)), half(0.000244140625));
    half _1305 = _1300 / (dot(_1326, _1326) * _1303);
    half _1359 = half(8192.0) * fma(half(-float(_1196)), _971, _1295);
    half _1363 = half(1.0) / (_1129 * _1359);
    half _1370 = half(2048.0) * _1129;
    float3 _1428 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1431 = dot(_1428, _1428);
    float3 _1436 = _1428 * rsqrt(fast::max(_1431, 9.9999999392252902907785028219223e-09));
    float _1440 = _1431 * float(frame.punctualLights[0].positionFalloff.w);
    float _1445 = fast::clamp(fma(-_1440, _1440, 1.0), 0.0, 1.0);
    float _1464 = fast::clamp(fma(dot(-_1436, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1475 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1445) * half(_1445)) / fast::max(_1431, 9.9999997473787516355514526367188e-05)) * half(_1464)) * half(_1464)), float3(65504.0));
    half3 _1591 = normalize(half3(_790) + half3(_1436));
    half _1530 = clamp(dot(_774, half3(_1436)), half(0.0), half(1.0));
    half _1534 = clamp(dot(_774, _1591), half(0.0), half(1.0));
    half4 _1660 = half4(cross(_774, _1591), half(params.facet_alpha) * _1534) * half(64.0);
    half _1629 = _1530 + _971;
    half _1637 = half(6.283185482025146484375) * max(mix((half(2.0) * _1530) * _971, _1629, half(params.facet_alpha)), half(0.000244140625));
    half _1639 = _1300 / (dot(_1660, _1660) * _1637);
    half _1693 = half(8192.0) * fma(half(-float(_1530)), _971, _1629);
    half _1697 = half(1.0) / (_1129 * _1693);
    half3 _1726 = (fma(half4(_1141).xyz, _1120 * _1083, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1036).xyz * (mix(half4(_1010).xxx, half4(_1010).yyy, half3(float3(params.facet_f0))) * _1029)) * _1085) + min(fma((half3(float3(params.facet_f0)) * min(_1305 * (_1305 * _1303), half(65504.0))) * _1029, (_848 * _1196) * _1085, (_1120 * ((((fma(_1363, _1359, half(2.0)) * pow(max(fma(half(-float(_1200)), _1200, half(1.0)), half(0.0)), half(0.5) * (_1363 * _1359))) * half(0.15915493667125701904296875)) * (_1196 * (_1363 * _1370))) * _1090)) * _848), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1639 * (_1639 * _1637), half(65504.0))) * _1029, (half3(_1475) * _1530) * _1085, (_1120 * ((((fma(_1697, _1693, half(2.0)) * pow(max(fma(half(-float(_1534)), _1534, half(1.0)), half(0.0)), half(0.5) * (_1697 * _1693))) * half(0.15915493667125701904296875)) * (_1530 * (_1697 * _1370))) * _1090)) * half3(_1475)), half3(float3(65504.0)));
    float3 _1762 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1765 = dot(_1762, _1762);
    float3 _1770 = _1762 * rsqrt(fast::max(_1765, 9.9999999392252902907785028219223e-09));
    float _1774 = _1765 * float(frame.punctualLights[1].positionFalloff.w);
    float _1779 = fast::clamp(fma(-_1774, _1774, 1.0), 0.0, 1.0);
    float _1798 = fast::clamp(fma(dot(-_1770, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1809 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1779) * half(_1779)) / fast::max(_1765, 9.9999997473787516355514526367188e-05)) * half(_1798)) * half(_1798)), float3(65504.0));
    half3 _1925 = normalize(half3(_790) + half3(_1770));
    half _1864 = clamp(dot(_774, half3(_1770)), half(0.0), half(1.0));
    half _1868 = clamp(dot(_774, _1925), half(0.0), half(1.0));
    half4 _1994 = half4(cross(_774, _1925), half(params.facet_alpha) * _1868) * half(64.0);
    half _1963 = _1864 + _971;
    half _1971 = half(6.283185482025146484375) * max(mix((half(2.0) * _1864) * _971, _1963, half(params.facet_alpha)), half(0.000244140625));
    half _1973 = _1300 / (dot(_1994, _1994) * _1971);
    half _2027 = half(8192.0) * fma(half(-float(_1864)), _971, _1963);
    half _2031 = half(1.0) / (_1129 * _2027);
    out.fragColor = float4(half4(_1726 + min(fma((half3(float3(params.facet_f0)) * min(_1973 * (_1973 * _1971), half(65504.0))) * _1029, (half3(_1809) * _1864) * _1085, (_1120 * ((((fma(_2031, _2027, half(2.0)) * pow(max(fma(half(-float(_1868)), _1868, half(1.0)), half(0.0)), half(0.5) * (_2031 * _2027))) * half(0.15915493667125701904296875)) * (_1864 * (_2031 * _1370))) * _1090)) * half3(_1809)), half3(float3(65504.0))), half(1.0)));
    return out;
}

