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
    float3 _653 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _800 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _804 = (half4(_800).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1759;
    do
    {
        half3 _817 = half4(in.v_tangent).xyz;
        if (float(dot(_817, _817)) == 0.0)
        {
            _1759 = normalize(half3(in.v_normal));
            break;
        }
        _1759 = normalize(((_817 * _804.x) + ((cross(half3(in.v_normal), _817) * half(in.v_tangent.w)) * _804.y)) + (half3(in.v_normal) * _804.z));
        break;
    } while(false);
    half _887 = max(dot(_1759, half3(_653)), half(9.9999997473787516355514526367188e-05));
    float4 _926 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_887, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _945 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_926).y) - half(1.0)));
    float4 _955 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_653), _1759)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _694 = half4(frame.lightDirection).xyz;
    half3 _1062 = normalize(half3(_653) + _694);
    half _1013 = clamp(dot(_1759, _694), half(0.0), half(1.0));
    half4 _1131 = half4(cross(_1759, _1062), half(params.facet_alpha) * clamp(dot(_1759, _1062), half(0.0), half(1.0))) * half(64.0);
    half _1105 = half(4096.0) * half(params.facet_alpha);
    half _1108 = half(6.283185482025146484375) * max(mix((half(2.0) * _1013) * _887, _1013 + _887, half(params.facet_alpha)), half(0.000244140625));
    half _1110 = _1105 / (dot(_1131, _1131) * _1108);
    float3 _1175 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1178 = dot(_1175, _1175);
    float3 _1183 = _1175 * rsqrt(fast::max(_1178, 9.9999999392252902907785028219223e-09));
    float _1187 = _1178 * float(frame.punctualLights[0].positionFalloff.w);
    float _1192 = fast::clamp(fma(-_1187, _1187, 1.0), 0.0, 1.0);
    float _1211 = fast::clamp(fma(dot(-_1183, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1321 = normalize(half3(_653) + half3(_1183));
    half _1272 = clamp(dot(_1759, half3(_1183)), half(0.0), half(1.0));
    half4 _1390 = half4(cross(_1759, _1321), half(params.facet_alpha) * clamp(dot(_1759, _1321), half(0.0), half(1.0))) * half(64.0);
    half _1367 = half(6.283185482025146484375) * max(mix((half(2.0) * _1272) * _887, _1272 + _887, half(params.facet_alpha)), half(0.000244140625));
    half _1369 = _1105 / (dot(_1390, _1390) * _1367);
    float3 _1434 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1437 = dot(_1434, _1434);
    float3 _1442 = _1434 * rsqrt(fast::max(_1437, 9.9999999392252902907785028219223e-09));
    float _1446 = _1437 * float(frame.punctualLights[1].positionFalloff.w);
    float _1451 = fast::clamp(fma(-_1446, _1446, 1.0), 0.0, 1.0);
    float _1470 = fast::clamp(fma(dot(-_1442, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1580 = normalize(half3(_653) + half3(_1442));
    half _1531 = clamp(dot(_1759, half3(_1442)), half(0.0), half(1.0));
    half4 _1649 = half4(cross(_1759, _1580), half(params.facet_alpha) * clamp(dot(_1759, _1580), half(0.0), half(1.0))) * half(64.0);
    half _1626 = half(6.283185482025146484375) * max(mix((half(2.0) * _1531) * _887, _1531 + _887, half(params.facet_alpha)), half(0.000244140625));
    half _1628 = _1105 / (dot(_1649, _1649) * _1626);
    half3 _1657 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_955).xyz * (mix(half4(_926).xxx, half4(_926).yyy, half3(float3(params.facet_f0))) * _945)) + min(((half3(float3(params.facet_f0)) * min(_1110 * (_1110 * _1108), half(65504.0))) * _945) * (half4(frame.lightColor).xyz * _1013), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1369 * (_1369 * _1367), half(65504.0))) * _945) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1192) * half(_1192)) / fast::max(_1178, 9.9999997473787516355514526367188e-05)) * half(_1211)) * half(_1211)), float3(65504.0))) * _1272), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1628 * (_1628 * _1626), half(65504.0))) * _945) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1451) * half(_1451)) / fast::max(_1437, 9.9999997473787516355514526367188e-05)) * half(_1470)) * half(_1470)), float3(65504.0))) * _1531), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1657, half(1.0)));
    return out;
}

