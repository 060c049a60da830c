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
    float3 _614 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _743 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _747 = (half4(_743).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1463;
    do
    {
        half3 _760 = half4(in.v_tangent).xyz;
        if (float(dot(_760, _760)) == 0.0)
        {
            _1463 = normalize(half3(in.v_normal));
            break;
        }
        _1463 = normalize(((_760 * _747.x) + ((cross(half3(in.v_normal), _760) * half(in.v_tangent.w)) * _747.y)) + (half3(in.v_normal) * _747.z));
        break;
    } while(false);
    half3 _834 = reflect(-half3(_614), _1463);
    float4 _870 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1463, half3(_614)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _896 = facet_environment.sample(facet_environmentSmplr, float3(_834), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _849 = mix(half4(_870).xxx, half4(_870).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_870).y) - half(1.0))));
    float3 _941 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _944 = dot(_941, _941);
    float3 _949 = _941 * rsqrt(fast::max(_944, 9.9999999392252902907785028219223e-09));
    float _953 = _944 * float(frame.punctualLights[0].positionFalloff.w);
    float _958 = fast::clamp(fma(-_953, _953, 1.0), 0.0, 1.0);
    float _977 = fast::clamp(fma(dot(-_949, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1109 = clamp(dot(_834, half3(_949)), half(0.0), half(1.0));
    half _1112 = _1109 * _1109;
    half4 _1527 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1112 * _1112, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1124 = _1527.x;
    float3 _1169 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1172 = dot(_1169, _1169);
    float3 _1177 = _1169 * rsqrt(fast::max(_1172, 9.9999999392252902907785028219223e-09));
    float _1181 = _1172 * float(frame.punctualLights[1].positionFalloff.w);
    float _1186 = fast::clamp(fma(-_1181, _1181, 1.0), 0.0, 1.0);
    float _1205 = fast::clamp(fma(dot(-_1177, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1337 = clamp(dot(_834, half3(_1177)), half(0.0), half(1.0));
    half _1340 = _1337 * _1337;
    half4 _1553 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1340 * _1340, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1352 = _1553.x;
    half3 _1361 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_896).xyz * _849) + min((_849 * ((_1124 * _1124) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_958) * half(_958)) / fast::max(_944, 9.9999997473787516355514526367188e-05)) * half(_977)) * half(_977)), float3(65504.0))) * clamp(dot(_1463, half3(_949)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_849 * ((_1352 * _1352) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1186) * half(_1186)) / fast::max(_1172, 9.9999997473787516355514526367188e-05)) * half(_1205)) * half(_1205)), float3(65504.0))) * clamp(dot(_1463, half3(_1177)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1361, half(1.0)));
    return out;
}

