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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _772 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _902 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _906 = (half4(_902).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1925;
    do
    {
        half3 _919 = half4(in.v_tangent).xyz;
        if (float(dot(_919, _919)) == 0.0)
        {
            _1925 = normalize(half3(in.v_normal));
            break;
        }
        _1925 = normalize(((_919 * _906.x) + ((cross(half3(in.v_normal), _919) * half(in.v_tangent.w)) * _906.y)) + (half3(in.v_normal) * _906.z));
        break;
    } while(false);
    half _955 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _965 = dfdx(float3(_1925));
    float3 _967 = dfdy(float3(_1925));
    half _978 = _955 * _955;
    float4 _995 = facet_irradiance.sample(facet_irradianceSmplr, float3(_1925), level(0.0));
    half _1071 = clamp(half(sqrt(sqrt(fast::min(fma(float(_978), float(_978), fast::min((dot(_965, _965) + dot(_967, _967)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1044 = max(dot(_1925, half3(_772)), half(9.9999997473787516355514526367188e-05));
    float4 _1078 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1044, _1071)), level(0.0));
    float4 _1097 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_772), _1925)), level(_1071 * (half(4.0) * (half(2.0) - _1071))));
    float3 _1142 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1145 = dot(_1142, _1142);
    float3 _1150 = _1142 * rsqrt(fast::max(_1145, 9.9999999392252902907785028219223e-09));
    float _1154 = _1145 * float(frame.punctualLights[0].positionFalloff.w);
    float _1159 = fast::clamp(fma(-_1154, _1154, 1.0), 0.0, 1.0);
    float _1178 = fast::clamp(fma(dot(-_1150, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1293 = _1071 * _1071;
    half _1238 = clamp(dot(_1925, half3(_1150)), half(0.0), half(1.0));
    float3 _1305 = fast::normalize(_772 + _1150);
    half _1345 = half(4096.0) * _1293;
    half4 _1370 = half4(cross(_1925, half3(_1305)), _1293 * clamp(dot(_1925, half3(_1305)), half(0.0), half(1.0))) * half(64.0);
    half _1351 = _1345 / dot(_1370, _1370);
    half _1381 = _1293 * _1293;
    half _1387 = fma(half(-float(_1293)), _1293, half(1.0));
    half _1391 = sqrt(fma(_1044 * _1044, _1387, _1381));
    half _1415 = half(1.0) - clamp(dot(half3(_1150), half3(_1305)), half(0.0), half(1.0));
    half _1418 = _1415 * _1415;
    half3 _1426 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1269 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1476 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1479 = dot(_1476, _1476);
    float3 _1484 = _1476 * rsqrt(fast::max(_1479, 9.9999999392252902907785028219223e-09));
    float _1488 = _1479 * float(frame.punctualLights[1].positionFalloff.w);
    float _1493 = fast::clamp(fma(-_1488, _1488, 1.0), 0.0, 1.0);
    float _1512 = fast::clamp(fma(dot(-_1484, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1572 = clamp(dot(_1925, half3(_1484)), half(0.0), half(1.0));
    float3 _1639 = fast::normalize(_772 + _1484);
    half4 _1704 = half4(cross(_1925, half3(_1639)), _1293 * clamp(dot(_1925, half3(_1639)), half(0.0), half(1.0))) * half(64.0);
    half _1685 = _1345 / dot(_1704, _1704);
    half _1749 = half(1.0) - clamp(dot(half3(_1484), half3(_1639)), half(0.0), half(1.0));
    half _1752 = _1749 * _1749;
    half3 _1774 = (fma(half3(float3(params.facet_diffuseColor)), half4(_995).xyz, half4(_1097).xyz * mix(half4(_1078).xxx, half4(_1078).yyy, half3(float3(params.facet_f0)))) + min((_1269 + ((half3(float3(params.facet_f0)) + (_1426 * ((_1418 * _1418) * _1415))) * min(min((_1351 * _1351) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1238, _1391, _1044 * sqrt(fma(_1238 * _1238, _1387, _1381))), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1159) * half(_1159)) / fast::max(_1145, 9.9999997473787516355514526367188e-05)) * half(_1178)) * half(_1178)), float3(65504.0))) * _1238), half3(float3(65504.0)))) + min((_1269 + ((half3(float3(params.facet_f0)) + (_1426 * ((_1752 * _1752) * _1749))) * min(min((_1685 * _1685) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1572, _1391, _1044 * sqrt(fma(_1572 * _1572, _1387, _1381))), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1493) * half(_1493)) / fast::max(_1479, 9.9999997473787516355514526367188e-05)) * half(_1512)) * half(_1512)), float3(65504.0))) * _1572), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1774, half(1.0)));
    return out;
}

