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
    float4 _923 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _927 = (half4(_923).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2198;
    do
    {
        half3 _940 = half4(in.v_tangent).xyz;
        if (float(dot(_940, _940)) == 0.0)
        {
            _2198 = normalize(half3(in.v_normal));
            break;
        }
        _2198 = normalize(((_940 * _927.x) + ((cross(half3(in.v_normal), _940) * half(in.v_tangent.w)) * _927.y)) + (half3(in.v_normal) * _927.z));
        break;
    } while(false);
    half _976 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _986 = dfdx(float3(_2198));
    float3 _988 = dfdy(float3(_2198));
    half _999 = _976 * _976;
    float4 _1016 = facet_irradiance.sample(facet_irradianceSmplr, float3(_2198), level(0.0));
    half _1092 = clamp(half(sqrt(sqrt(fast::min(fma(float(_999), float(_999), fast::min((dot(_986, _986) + dot(_988, _988)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1065 = max(dot(_2198, half3(_772)), half(9.9999997473787516355514526367188e-05));
    float4 _1099 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1065, _1092)), level(0.0));
    float4 _1118 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_772), _2198)), level(_1092 * (half(4.0) * (half(2.0) - _1092))));
    half _1230 = _1092 * _1092;
    half _1175 = clamp(dot(_2198, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1242 = fast::normalize(_772 + frame.lightDirection.xyz);
    half _1282 = half(4096.0) * _1230;
    half4 _1307 = half4(cross(_2198, half3(_1242)), _1230 * clamp(dot(_2198, half3(_1242)), half(0.0), half(1.0))) * half(64.0);
    half _1288 = _1282 / dot(_1307, _1307);
    half _1318 = _1230 * _1230;
    half _1324 = fma(half(-float(_1230)), _1230, half(1.0));
    half _1328 = sqrt(fma(_1065 * _1065, _1324, _1318));
    half _1352 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1242)), half(0.0), half(1.0));
    half _1355 = _1352 * _1352;
    half3 _1363 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1206 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1413 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1416 = dot(_1413, _1413);
    float3 _1421 = _1413 * rsqrt(fast::max(_1416, 9.9999999392252902907785028219223e-09));
    float _1425 = _1416 * float(frame.punctualLights[0].positionFalloff.w);
    float _1430 = fast::clamp(fma(-_1425, _1425, 1.0), 0.0, 1.0);
    float _1449 = fast::clamp(fma(dot(-_1421, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1509 = clamp(dot(_2198, half3(_1421)), half(0.0), half(1.0));
    float3 _1576 = fast::normalize(_772 + _1421);
    half4 _1641 = half4(cross(_2198, half3(_1576)), _1230 * clamp(dot(_2198, half3(_1576)), half(0.0), half(1.0))) * half(64.0);
    half _1622 = _1282 / dot(_1641, _1641);
    half _1686 = half(1.0) - clamp(dot(half3(_1421), half3(_1576)), half(0.0), half(1.0));
    half _1689 = _1686 * _1686;
    half3 _1711 = (fma(half3(float3(params.facet_diffuseColor)), half4(_1016).xyz, half4(_1118).xyz * mix(half4(_1099).xxx, half4(_1099).yyy, half3(float3(params.facet_f0)))) + min((_1206 + ((half3(float3(params.facet_f0)) + (_1363 * ((_1355 * _1355) * _1352))) * min(min((_1288 * _1288) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1175, _1328, _1065 * sqrt(fma(_1175 * _1175, _1324, _1318))), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _1175), half3(float3(65504.0)))) + min((_1206 + ((half3(float3(params.facet_f0)) + (_1363 * ((_1689 * _1689) * _1686))) * min(min((_1622 * _1622) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1509, _1328, _1065 * sqrt(fma(_1509 * _1509, _1324, _1318))), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1430) * half(_1430)) / fast::max(_1416, 9.9999997473787516355514526367188e-05)) * half(_1449)) * half(_1449)), float3(65504.0))) * _1509), half3(float3(65504.0)));
    float3 _1747 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1750 = dot(_1747, _1747);
    float3 _1755 = _1747 * rsqrt(fast::max(_1750, 9.9999999392252902907785028219223e-09));
    float _1759 = _1750 * float(frame.punctualLights[1].positionFalloff.w);
    float _1764 = fast::clamp(fma(-_1759, _1759, 1.0), 0.0, 1.0);
    float _1783 = fast::clamp(fma(dot(-_1755, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1843 = clamp(dot(_2198, half3(_1755)), half(0.0), half(1.0));
    float3 _1910 = fast::normalize(_772 + _1755);
    half4 _1975 = half4(cross(_2198, half3(_1910)), _1230 * clamp(dot(_2198, half3(_1910)), half(0.0), half(1.0))) * half(64.0);
    half _1956 = _1282 / dot(_1975, _1975);
    half _2020 = half(1.0) - clamp(dot(half3(_1755), half3(_1910)), half(0.0), half(1.0));
    half _2023 = _2020 * _2020;
    half3 _2045 = _1711 + min((_1206 + ((half3(float3(params.facet_f0)) + (_1363 * ((_2023 * _2023) * _2020))) * min(min((_1956 * _1956) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1843, _1328, _1065 * sqrt(fma(_1843 * _1843, _1324, _1318))), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1764) * half(_1764)) / fast::max(_1750, 9.9999997473787516355514526367188e-05)) * half(_1783)) * half(_1783)), float3(65504.0))) * _1843), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2045, half(1.0)));
    return out;
}

