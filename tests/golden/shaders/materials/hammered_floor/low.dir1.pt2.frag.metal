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
    float4 _768 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _772 = (half4(_768).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1635;
    do
    {
        half3 _785 = half4(in.v_tangent).xyz;
        if (float(dot(_785, _785)) == 0.0)
        {
            _1635 = normalize(half3(in.v_normal));
            break;
        }
        _1635 = normalize(((_785 * _772.x) + ((cross(half3(in.v_normal), _785) * half(in.v_tangent.w)) * _772.y)) + (half3(in.v_normal) * _772.z));
        break;
    } while(false);
    half3 _859 = reflect(-half3(_618), _1635);
    float4 _895 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1635, half3(_618)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _924 = facet_environment.sample(facet_environmentSmplr, float3(_859), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _874 = mix(half4(_895).xxx, half4(_895).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_895).y) - half(1.0))));
    half3 _659 = half4(frame.lightDirection).xyz;
    half _1053 = clamp(dot(_859, _659), half(0.0), half(1.0));
    half _1056 = _1053 * _1053;
    half4 _1690 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1056 * _1056, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1068 = _1690.x;
    float3 _1113 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1116 = dot(_1113, _1113);
    float3 _1121 = _1113 * rsqrt(fast::max(_1116, 9.9999999392252902907785028219223e-09));
    float _1125 = _1116 * float(frame.punctualLights[0].positionFalloff.w);
    float _1130 = fast::clamp(fma(-_1125, _1125, 1.0), 0.0, 1.0);
    float _1149 = fast::clamp(fma(dot(-_1121, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1281 = clamp(dot(_859, half3(_1121)), half(0.0), half(1.0));
    half _1284 = _1281 * _1281;
    half4 _1715 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1284 * _1284, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1296 = _1715.x;
    float3 _1341 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1344 = dot(_1341, _1341);
    float3 _1349 = _1341 * rsqrt(fast::max(_1344, 9.9999999392252902907785028219223e-09));
    float _1353 = _1344 * float(frame.punctualLights[1].positionFalloff.w);
    float _1358 = fast::clamp(fma(-_1353, _1353, 1.0), 0.0, 1.0);
    float _1377 = fast::clamp(fma(dot(-_1349, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1509 = clamp(dot(_859, half3(_1349)), half(0.0), half(1.0));
    half _1512 = _1509 * _1509;
    half4 _1741 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1512 * _1512, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1524 = _1741.x;
    half3 _1533 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_924).xyz * _874) + min((_874 * ((_1068 * _1068) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1635, _659), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_874 * ((_1296 * _1296) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1130) * half(_1130)) / fast::max(_1116, 9.9999997473787516355514526367188e-05)) * half(_1149)) * half(_1149)), float3(65504.0))) * clamp(dot(_1635, half3(_1121)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_874 * ((_1524 * _1524) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1358) * half(_1358)) / fast::max(_1344, 9.9999997473787516355514526367188e-05)) * half(_1377)) * half(_1377)), float3(65504.0))) * clamp(dot(_1635, half3(_1349)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1533, half(1.0)));
    return out;
}

