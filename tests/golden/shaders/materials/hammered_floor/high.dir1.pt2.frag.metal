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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _898 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1049 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _1053 = (half4(_1049).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2467;
    do
    {
        half3 _1066 = half4(in.v_tangent).xyz;
        if (float(dot(_1066, _1066)) == 0.0)
        {
            _2467 = normalize(half3(in.v_normal));
            break;
        }
        _2467 = normalize(((_1066 * _1053.x) + ((cross(half3(in.v_normal), _1066) * half(in.v_tangent.w)) * _1053.y)) + (half3(in.v_normal) * _1053.z));
        break;
    } while(false);
    half _1102 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _1112 = dfdx(float3(_2467));
    float3 _1114 = dfdy(float3(_2467));
    half _1125 = _1102 * _1102;
    half3 _1243 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2467.y)) + (half4(frame.sh[2]).xyz * _2467.z)) + (half4(frame.sh[3]).xyz * _2467.x)) + (((((half4(frame.sh[4]).xyz * (_2467.x * _2467.y)) + (half4(frame.sh[5]).xyz * (_2467.y * _2467.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2467.z, _2467.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2467.x * _2467.z))) + (half4(frame.sh[8]).xyz * fma(_2467.x, _2467.x, half(-float(_2467.y * _2467.y))))), half3(float3(0.0)));
    half _1326 = clamp(half(sqrt(sqrt(fast::min(fma(float(_1125), float(_1125), fast::min((dot(_1112, _1112) + dot(_1114, _1114)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1293 = max(dot(_2467, half3(_898)), half(9.9999997473787516355514526367188e-05));
    float4 _1333 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1293, _1326)), level(0.0));
    half3 _1352 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1333).y) - half(1.0)));
    float4 _1362 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_898), _2467)), level(_1326 * (half(4.0) * (half(2.0) - _1326))));
    half _1477 = _1326 * _1326;
    float3 _1489 = fast::normalize(_898 + frame.lightDirection.xyz);
    half _1422 = clamp(dot(_2467, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1529 = half(4096.0) * _1477;
    half4 _1554 = half4(cross(_2467, half3(_1489)), _1477 * clamp(dot(_2467, half3(_1489)), half(0.0), half(1.0))) * half(64.0);
    half _1535 = _1529 / dot(_1554, _1554);
    half _1565 = _1477 * _1477;
    half _1571 = fma(half(-float(_1477)), _1477, half(1.0));
    half _1575 = sqrt(fma(_1293 * _1293, _1571, _1565));
    half _1599 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1489)), half(0.0), half(1.0));
    half _1602 = _1599 * _1599;
    half3 _1610 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1453 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1660 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1663 = dot(_1660, _1660);
    float3 _1668 = _1660 * rsqrt(fast::max(_1663, 9.9999999392252902907785028219223e-09));
    float _1672 = _1663 * float(frame.punctualLights[0].positionFalloff.w);
    float _1677 = fast::clamp(fma(-_1672, _1672, 1.0), 0.0, 1.0);
    float _1696 = fast::clamp(fma(dot(-_1668, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1826 = fast::normalize(_898 + _1668);
    half _1759 = clamp(dot(_2467, half3(_1668)), half(0.0), half(1.0));
    half4 _1891 = half4(cross(_2467, half3(_1826)), _1477 * clamp(dot(_2467, half3(_1826)), half(0.0), half(1.0))) * half(64.0);
    half _1872 = _1529 / dot(_1891, _1891);
    half _1936 = half(1.0) - clamp(dot(half3(_1668), half3(_1826)), half(0.0), half(1.0));
    half _1939 = _1936 * _1936;
    half3 _1961 = (fma(half3(float3(params.facet_diffuseColor)), _1243, half4(_1362).xyz * (mix(half4(_1333).xxx, half4(_1333).yyy, half3(float3(params.facet_f0))) * _1352)) + min(fma((half3(float3(params.facet_f0)) + (_1610 * ((_1602 * _1602) * _1599))) * min(min((_1535 * _1535) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1422, _1575, _1293 * sqrt(fma(_1422 * _1422, _1571, _1565))), half(65504.0)), half(65504.0)), _1352, _1453) * (half4(frame.lightColor).xyz * _1422), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1610 * ((_1939 * _1939) * _1936))) * min(min((_1872 * _1872) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1759, _1575, _1293 * sqrt(fma(_1759 * _1759, _1571, _1565))), half(65504.0)), half(65504.0)), _1352, _1453) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1677) * half(_1677)) / fast::max(_1663, 9.9999997473787516355514526367188e-05)) * half(_1696)) * half(_1696)), float3(65504.0))) * _1759), half3(float3(65504.0)));
    float3 _1997 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2000 = dot(_1997, _1997);
    float3 _2005 = _1997 * rsqrt(fast::max(_2000, 9.9999999392252902907785028219223e-09));
    float _2009 = _2000 * float(frame.punctualLights[1].positionFalloff.w);
    float _2014 = fast::clamp(fma(-_2009, _2009, 1.0), 0.0, 1.0);
    float _2033 = fast::clamp(fma(dot(-_2005, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2163 = fast::normalize(_898 + _2005);
    half _2096 = clamp(dot(_2467, half3(_2005)), half(0.0), half(1.0));
    half4 _2228 = half4(cross(_2467, half3(_2163)), _1477 * clamp(dot(_2467, half3(_2163)), half(0.0), half(1.0))) * half(64.0);
    half _2209 = _1529 / dot(_2228, _2228);
    half _2273 = half(1.0) - clamp(dot(half3(_2005), half3(_2163)), half(0.0), half(1.0));
    half _2276 = _2273 * _2273;
    half3 _2298 = _1961 + min(fma((half3(float3(params.facet_f0)) + (_1610 * ((_2276 * _2276) * _2273))) * min(min((_2209 * _2209) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2096, _1575, _1293 * sqrt(fma(_2096 * _2096, _1571, _1565))), half(65504.0)), half(65504.0)), _1352, _1453) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2014) * half(_2014)) / fast::max(_2000, 9.9999997473787516355514526367188e-05)) * half(_2033)) * half(_2033)), float3(65504.0))) * _2096), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2298, half(1.0)));
    return out;
}

