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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _653 = normalize(half3(in.v_normal));
    float3 _669 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _815 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _923 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _815)), half(0.0), half(1.0));
    half3 _931 = half3((half(0.1599999964237213134765625) * _923) * _923);
    half _940 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _815)), half(0.08900000154972076416015625), half(1.0));
    half _883 = max(dot(_653, half3(_669)), half(9.9999997473787516355514526367188e-05));
    float4 _947 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_883, _940)), level(0.0));
    half3 _966 = half3(float3(1.0)) + (_931 * ((half(1.0) / half4(_947).y) - half(1.0)));
    float4 _973 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_669), _653)), level(_940 * half(4.0)));
    half3 _706 = half4(frame.lightDirection).xyz;
    half _1104 = _940 * _940;
    half3 _1115 = normalize(half3(_669) + _706);
    half _1031 = clamp(dot(_653, _706), half(0.0), half(1.0));
    half3 _1178 = cross(_653, _1115) * half(64.0);
    half _1181 = half(64.0) * _1104;
    half _1182 = clamp(dot(_653, _1115), half(0.0), half(1.0)) * _1181;
    half _1158 = half(4096.0) * _1104;
    half _1161 = half(6.283185482025146484375) * max(mix((half(2.0) * _1031) * _883, _1031 + _883, _1104), half(0.000244140625));
    half _1163 = _1158 / (fma(_1182, _1182, dot(_1178, _1178)) * _1161);
    float3 _1230 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1233 = dot(_1230, _1230);
    float3 _1238 = _1230 * rsqrt(fast::max(_1233, 9.9999999392252902907785028219223e-09));
    float _1242 = _1233 * float(frame.punctualLights[0].positionFalloff.w);
    float _1247 = fast::clamp(fma(-_1242, _1242, 1.0), 0.0, 1.0);
    float _1266 = fast::clamp(fma(dot(-_1238, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1411 = normalize(half3(_669) + half3(_1238));
    half _1327 = clamp(dot(_653, half3(_1238)), half(0.0), half(1.0));
    half3 _1474 = cross(_653, _1411) * half(64.0);
    half _1478 = clamp(dot(_653, _1411), half(0.0), half(1.0)) * _1181;
    half _1457 = half(6.283185482025146484375) * max(mix((half(2.0) * _1327) * _883, _1327 + _883, _1104), half(0.000244140625));
    half _1459 = _1158 / (fma(_1478, _1478, dot(_1474, _1474)) * _1457);
    float3 _1526 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1529 = dot(_1526, _1526);
    float3 _1534 = _1526 * rsqrt(fast::max(_1529, 9.9999999392252902907785028219223e-09));
    float _1538 = _1529 * float(frame.punctualLights[1].positionFalloff.w);
    float _1543 = fast::clamp(fma(-_1538, _1538, 1.0), 0.0, 1.0);
    float _1562 = fast::clamp(fma(dot(-_1534, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1707 = normalize(half3(_669) + half3(_1534));
    half _1623 = clamp(dot(_653, half3(_1534)), half(0.0), half(1.0));
    half3 _1770 = cross(_653, _1707) * half(64.0);
    half _1774 = clamp(dot(_653, _1707), half(0.0), half(1.0)) * _1181;
    half _1753 = half(6.283185482025146484375) * max(mix((half(2.0) * _1623) * _883, _1623 + _883, _1104), half(0.000244140625));
    half _1755 = _1158 / (fma(_1774, _1774, dot(_1770, _1770)) * _1753);
    half3 _1786 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_815))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_973).xyz * (mix(half4(_947).xxx, half4(_947).yyy, _931) * _966)) + min(((_931 * min(_1163 * (_1163 * _1161), half(65504.0))) * _966) * (half4(frame.lightColor).xyz * _1031), half3(float3(65504.0)))) + min(((_931 * min(_1459 * (_1459 * _1457), half(65504.0))) * _966) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1247) * half(_1247)) / fast::max(_1233, 9.9999997473787516355514526367188e-05)) * half(_1266)) * half(_1266)), float3(65504.0))) * _1327), half3(float3(65504.0)))) + min(((_931 * min(_1755 * (_1755 * _1753), half(65504.0))) * _966) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1543) * half(_1543)) / fast::max(_1529, 9.9999997473787516355514526367188e-05)) * half(_1562)) * half(_1562)), float3(65504.0))) * _1623), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1786, half(1.0)));
    return out;
}

