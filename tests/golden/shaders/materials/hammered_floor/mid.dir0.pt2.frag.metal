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
    float4 _779 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _783 = (half4(_779).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1563;
    do
    {
        half3 _796 = half4(in.v_tangent).xyz;
        if (float(dot(_796, _796)) == 0.0)
        {
            _1563 = normalize(half3(in.v_normal));
            break;
        }
        _1563 = normalize(((_796 * _783.x) + ((cross(half3(in.v_normal), _796) * half(in.v_tangent.w)) * _783.y)) + (half3(in.v_normal) * _783.z));
        break;
    } while(false);
    half _866 = max(dot(_1563, half3(_653)), half(9.9999997473787516355514526367188e-05));
    float4 _905 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_866, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _924 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_905).y) - half(1.0)));
    float4 _934 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_653), _1563)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _979 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _982 = dot(_979, _979);
    float3 _987 = _979 * rsqrt(fast::max(_982, 9.9999999392252902907785028219223e-09));
    float _991 = _982 * float(frame.punctualLights[0].positionFalloff.w);
    float _996 = fast::clamp(fma(-_991, _991, 1.0), 0.0, 1.0);
    float _1015 = fast::clamp(fma(dot(-_987, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1125 = normalize(half3(_653) + half3(_987));
    half _1076 = clamp(dot(_1563, half3(_987)), half(0.0), half(1.0));
    half4 _1194 = half4(cross(_1563, _1125), half(params.facet_alpha) * clamp(dot(_1563, _1125), half(0.0), half(1.0))) * half(64.0);
    half _1168 = half(4096.0) * half(params.facet_alpha);
    half _1171 = half(6.283185482025146484375) * max(mix((half(2.0) * _1076) * _866, _1076 + _866, half(params.facet_alpha)), half(0.000244140625));
    half _1173 = _1168 / (dot(_1194, _1194) * _1171);
    float3 _1238 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1241 = dot(_1238, _1238);
    float3 _1246 = _1238 * rsqrt(fast::max(_1241, 9.9999999392252902907785028219223e-09));
    float _1250 = _1241 * float(frame.punctualLights[1].positionFalloff.w);
    float _1255 = fast::clamp(fma(-_1250, _1250, 1.0), 0.0, 1.0);
    float _1274 = fast::clamp(fma(dot(-_1246, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1384 = normalize(half3(_653) + half3(_1246));
    half _1335 = clamp(dot(_1563, half3(_1246)), half(0.0), half(1.0));
    half4 _1453 = half4(cross(_1563, _1384), half(params.facet_alpha) * clamp(dot(_1563, _1384), half(0.0), half(1.0))) * half(64.0);
    half _1430 = half(6.283185482025146484375) * max(mix((half(2.0) * _1335) * _866, _1335 + _866, half(params.facet_alpha)), half(0.000244140625));
    half _1432 = _1168 / (dot(_1453, _1453) * _1430);
    half3 _1461 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_934).xyz * (mix(half4(_905).xxx, half4(_905).yyy, half3(float3(params.facet_f0))) * _924)) + min(((half3(float3(params.facet_f0)) * min(_1173 * (_1173 * _1171), half(65504.0))) * _924) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_996) * half(_996)) / fast::max(_982, 9.9999997473787516355514526367188e-05)) * half(_1015)) * half(_1015)), float3(65504.0))) * _1076), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1432 * (_1432 * _1430), half(65504.0))) * _924) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1255) * half(_1255)) / fast::max(_1241, 9.9999997473787516355514526367188e-05)) * half(_1274)) * half(_1274)), float3(65504.0))) * _1335), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1461, half(1.0)));
    return out;
}

