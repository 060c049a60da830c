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
    float4 _779 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _783 = (half4(_779).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1702;
    do
    {
        half3 _796 = half4(in.v_tangent).xyz;
        if (float(dot(_796, _796)) == 0.0)
        {
            _1702 = normalize(half3(in.v_normal));
            break;
        }
        _1702 = normalize(((_796 * _783.x) + ((cross(half3(in.v_normal), _796) * half(in.v_tangent.w)) * _783.y)) + (half3(in.v_normal) * _783.z));
        break;
    } while(false);
    half _866 = max(dot(_1702, half3(_632)), half(9.9999997473787516355514526367188e-05));
    float4 _905 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_866, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _924 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_905).y) - half(1.0)));
    float4 _931 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_632), _1702)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _673 = half4(frame.lightDirection).xyz;
    half3 _1038 = normalize(half3(_632) + _673);
    half _989 = clamp(dot(_1702, _673), half(0.0), half(1.0));
    half3 _1065 = cross(_1702, _1038);
    half _1068 = clamp(dot(_1702, _1038), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1085 = max(mix((half(2.0) * _989) * _866, _989 + _866, half(params.facet_alpha)), half(0.000244140625));
    half _1087 = half(1024.0) * half(params.facet_alpha);
    half _1092 = _1087 / (fma(_1068, _1068, dot(_1065, _1065)) * (half(6433.98193359375) * _1085));
    float3 _1140 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1143 = dot(_1140, _1140);
    float3 _1148 = _1140 * rsqrt(fast::max(_1143, 9.9999999392252902907785028219223e-09));
    float _1152 = _1143 * float(frame.punctualLights[0].positionFalloff.w);
    float _1157 = fast::clamp(fma(-_1152, _1152, 1.0), 0.0, 1.0);
    float _1176 = fast::clamp(fma(dot(-_1148, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1286 = normalize(half3(_632) + half3(_1148));
    half _1237 = clamp(dot(_1702, half3(_1148)), half(0.0), half(1.0));
    half3 _1313 = cross(_1702, _1286);
    half _1316 = clamp(dot(_1702, _1286), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1333 = max(mix((half(2.0) * _1237) * _866, _1237 + _866, half(params.facet_alpha)), half(0.000244140625));
    half _1340 = _1087 / (fma(_1316, _1316, dot(_1313, _1313)) * (half(6433.98193359375) * _1333));
    float3 _1388 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1391 = dot(_1388, _1388);
    float3 _1396 = _1388 * rsqrt(fast::max(_1391, 9.9999999392252902907785028219223e-09));
    float _1400 = _1391 * float(frame.punctualLights[1].positionFalloff.w);
    float _1405 = fast::clamp(fma(-_1400, _1400, 1.0), 0.0, 1.0);
    float _1424 = fast::clamp(fma(dot(-_1396, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1534 = normalize(half3(_632) + half3(_1396));
    half _1485 = clamp(dot(_1702, half3(_1396)), half(0.0), half(1.0));
    half3 _1561 = cross(_1702, _1534);
    half _1564 = clamp(dot(_1702, _1534), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1581 = max(mix((half(2.0) * _1485) * _866, _1485 + _866, half(params.facet_alpha)), half(0.000244140625));
    half _1588 = _1087 / (fma(_1564, _1564, dot(_1561, _1561)) * (half(6433.98193359375) * _1581));
    half3 _1600 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_931).xyz * (mix(half4(_905).xxx, half4(_905).yyy, half3(float3(params.facet_f0))) * _924)) + min(((half3(float3(params.facet_f0)) * min(_1092 * (_1092 * (half(6.283185482025146484375) * _1085)), half(65504.0))) * _924) * (half4(frame.lightColor).xyz * _989), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1340 * (_1340 * (half(6.283185482025146484375) * _1333)), half(65504.0))) * _924) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1157) * half(_1157)) / fast::max(_1143, 9.9999997473787516355514526367188e-05)) * half(_1176)) * half(_1176)), float3(65504.0))) * _1237), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1588 * (_1588 * (half(6.283185482025146484375) * _1581)), half(65504.0))) * _924) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1405) * half(_1405)) / fast::max(_1391, 9.9999997473787516355514526367188e-05)) * half(_1424)) * half(_1424)), float3(65504.0))) * _1485), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1600, half(1.0)));
    return out;
}

