#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _545 = normalize(half3(in.v_normal));
    float3 _561 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _674 = facet_irradiance.sample(facet_irradianceSmplr, float3(_545), level(0.0));
    half _714 = max(dot(_545, half3(_561)), half(9.9999997473787516355514526367188e-05));
    float4 _719 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_714, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1374 = half4(_719);
    half _732 = _1374.z;
    half _734 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _732, half(1.0));
    half4 _1378 = half4(_719);
    half _739 = _1378.w;
    float4 _748 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_561), _545)), level(params.facet_sheenLod));
    float3 _818 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _821 = dot(_818, _818);
    float3 _826 = _818 * rsqrt(fast::max(_821, 9.9999999392252902907785028219223e-09));
    float _830 = _821 * float(frame.punctualLights[0].positionFalloff.w);
    float _835 = fast::clamp(fma(-_830, _830, 1.0), 0.0, 1.0);
    float _854 = fast::clamp(fma(dot(-_826, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _888 = dot(_545, half3(_826));
    half _890 = clamp(_888, half(0.0), half(1.0));
    half _902 = clamp(dot(_545, normalize(half3(_561) + half3(_826))), half(0.0), half(1.0));
    half _971 = half(8192.0) * fma(half(-float(_890)), _714, _890 + _714);
    half _975 = half(1.0) / (half(params.facet_alpha) * _971);
    half _982 = half(2048.0) * half(params.facet_alpha);
    half3 _935 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_888 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_890), half3(float3(0.0)), half3(float3(1.0)))) * _734) + (half3(float3(params.facet_sheenColor)) * ((((fma(_975, _971, half(2.0)) * pow(max(fma(half(-float(_902)), _902, half(1.0)), half(0.0)), half(0.5) * (_975 * _971))) * half(0.15915493667125701904296875)) * (_890 * (_975 * _982))) * _739))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_835) * half(_835)) / fast::max(_821, 9.9999997473787516355514526367188e-05)) * half(_854)) * half(_854)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1046 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1049 = dot(_1046, _1046);
    float3 _1054 = _1046 * rsqrt(fast::max(_1049, 9.9999999392252902907785028219223e-09));
    float _1058 = _1049 * float(frame.punctualLights[1].positionFalloff.w);
    float _1063 = fast::clamp(fma(-_1058, _1058, 1.0), 0.0, 1.0);
    float _1082 = fast::clamp(fma(dot(-_1054, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1116 = dot(_545, half3(_1054));
    half _1118 = clamp(_1116, half(0.0), half(1.0));
    half _1130 = clamp(dot(_545, normalize(half3(_561) + half3(_1054))), half(0.0), half(1.0));
    half _1199 = half(8192.0) * fma(half(-float(_1118)), _714, _1118 + _714);
    half _1203 = half(1.0) / (half(params.facet_alpha) * _1199);
    half3 _1163 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1116 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1118), half3(float3(0.0)), half3(float3(1.0)))) * _734) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1203, _1199, half(2.0)) * pow(max(fma(half(-float(_1130)), _1130, half(1.0)), half(0.0)), half(0.5) * (_1203 * _1199))) * half(0.15915493667125701904296875)) * (_1118 * (_1203 * _982))) * _739))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1063) * half(_1063)) / fast::max(_1049, 9.9999997473787516355514526367188e-05)) * half(_1082)) * half(_1082)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_748).xyz, half3(float3(params.facet_sheenColor)) * _732, (half3(float3(params.facet_diffuseColor)) * half4(_674).xyz) * _734) + _935) + _1163, half(1.0)));
    return out;
}

