#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float tiling;
    float roughness;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _618 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _747 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _751 = (half4(_747).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1470;
    do
    {
        half3 _764 = half4(in.v_tangent).xyz;
        if (float(dot(_764, _764)) == 0.0)
        {
            _1470 = normalize(half3(in.v_normal));
            break;
        }
        _1470 = normalize(((_764 * _751.x) + ((cross(half3(in.v_normal), _764) * half(in.v_tangent.w)) * _751.y)) + (half3(in.v_normal) * _751.z));
        break;
    } while(false);
    half3 _838 = reflect(-half3(_618), _1470);
    float4 _874 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1470, half3(_618)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _903 = facet_environment.sample(facet_environmentSmplr, float3(_838), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _853 = mix(half4(_874).xxx, half4(_874).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_874).y) - half(1.0))));
    float3 _948 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _951 = dot(_948, _948);
    float3 _956 = _948 * rsqrt(fast::max(_951, 9.9999999392252902907785028219223e-09));
    float _960 = _951 * float(frame.punctualLights[0].positionFalloff.w);
    float _965 = fast::clamp(fma(-_960, _960, 1.0), 0.0, 1.0);
    float _984 = fast::clamp(fma(dot(-_956, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1116 = clamp(dot(_838, half3(_956)), half(0.0), half(1.0));
    half _1119 = _1116 * _1116;
    half4 _1536 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1119 * _1119, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1131 = _1536.x;
    float3 _1176 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1179 = dot(_1176, _1176);
    float3 _1184 = _1176 * rsqrt(fast::max(_1179, 9.9999999392252902907785028219223e-09));
    float _1188 = _1179 * float(frame.punctualLights[1].positionFalloff.w);
    float _1193 = fast::clamp(fma(-_1188, _1188, 1.0), 0.0, 1.0);
    float _1212 = fast::clamp(fma(dot(-_1184, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1344 = clamp(dot(_838, half3(_1184)), half(0.0), half(1.0));
    half _1347 = _1344 * _1344;
    half4 _1562 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1347 * _1347, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1359 = _1562.x;
    half3 _1368 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_903).xyz * _853) + min((_853 * ((_1131 * _1131) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_965) * half(_965)) / fast::max(_951, 9.9999997473787516355514526367188e-05)) * half(_984)) * half(_984)), float3(65504.0))) * clamp(dot(_1470, half3(_956)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_853 * ((_1359 * _1359) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1193) * half(_1193)) / fast::max(_1179, 9.9999997473787516355514526367188e-05)) * half(_1212)) * half(_1212)), float3(65504.0))) * clamp(dot(_1470, half3(_1184)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1368, half(1.0)));
    return out;
}

