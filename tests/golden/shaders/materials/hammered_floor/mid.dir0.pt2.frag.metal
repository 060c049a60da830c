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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _632 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _758 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _762 = (half4(_758).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1517;
    do
    {
        half3 _775 = half4(in.v_tangent).xyz;
        if (float(dot(_775, _775)) == 0.0)
        {
            _1517 = normalize(half3(in.v_normal));
            break;
        }
        _1517 = normalize(((_775 * _762.x) + ((cross(half3(in.v_normal), _775) * half(in.v_tangent.w)) * _762.y)) + (half3(in.v_normal) * _762.z));
        break;
    } while(false);
    half _845 = max(dot(_1517, half3(_632)), half(9.9999997473787516355514526367188e-05));
    float4 _884 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _903 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_884).y) - half(1.0)));
    float4 _910 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_632), _1517)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _955 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _958 = dot(_955, _955);
    float3 _963 = _955 * rsqrt(fast::max(_958, 9.9999999392252902907785028219223e-09));
    float _967 = _958 * float(frame.punctualLights[0].positionFalloff.w);
    float _972 = fast::clamp(fma(-_967, _967, 1.0), 0.0, 1.0);
    float _991 = fast::clamp(fma(dot(-_963, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1101 = normalize(half3(_632) + half3(_963));
    half _1052 = clamp(dot(_1517, half3(_963)), half(0.0), half(1.0));
    half3 _1128 = cross(_1517, _1101);
    half _1131 = clamp(dot(_1517, _1101), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1148 = max(mix((half(2.0) * _1052) * _845, _1052 + _845, half(params.facet_alpha)), half(0.000244140625));
    half _1150 = half(1024.0) * half(params.facet_alpha);
    half _1155 = _1150 / (fma(_1131, _1131, dot(_1128, _1128)) * (half(6433.98193359375) * _1148));
    float3 _1203 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1206 = dot(_1203, _1203);
    float3 _1211 = _1203 * rsqrt(fast::max(_1206, 9.9999999392252902907785028219223e-09));
    float _1215 = _1206 * float(frame.punctualLights[1].positionFalloff.w);
    float _1220 = fast::clamp(fma(-_1215, _1215, 1.0), 0.0, 1.0);
    float _1239 = fast::clamp(fma(dot(-_1211, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1349 = normalize(half3(_632) + half3(_1211));
    half _1300 = clamp(dot(_1517, half3(_1211)), half(0.0), half(1.0));
    half3 _1376 = cross(_1517, _1349);
    half _1379 = clamp(dot(_1517, _1349), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1396 = max(mix((half(2.0) * _1300) * _845, _1300 + _845, half(params.facet_alpha)), half(0.000244140625));
    half _1403 = _1150 / (fma(_1379, _1379, dot(_1376, _1376)) * (half(6433.98193359375) * _1396));
    half3 _1415 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_910).xyz * (mix(half4(_884).xxx, half4(_884).yyy, half3(float3(params.facet_f0))) * _903)) + min(((half3(float3(params.facet_f0)) * min(_1155 * (_1155 * (half(6.283185482025146484375) * _1148)), half(65504.0))) * _903) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_972) * half(_972)) / fast::max(_958, 9.9999997473787516355514526367188e-05)) * half(_991)) * half(_991)), float3(65504.0))) * _1052), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1403 * (_1403 * (half(6.283185482025146484375) * _1396)), half(65504.0))) * _903) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1220) * half(_1220)) / fast::max(_1206, 9.9999997473787516355514526367188e-05)) * half(_1239)) * half(_1239)), float3(65504.0))) * _1300), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1415, half(1.0)));
    return out;
}

