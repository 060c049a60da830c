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
    float3 _734 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _888 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _892 = (half4(_888).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2104;
    do
    {
        half3 _905 = half4(in.v_tangent).xyz;
        if (float(dot(_905, _905)) == 0.0)
        {
            _2104 = normalize(half3(in.v_normal));
            break;
        }
        _2104 = normalize(((_905 * _892.x) + ((cross(half3(in.v_normal), _905) * half(in.v_tangent.w)) * _892.y)) + (half3(in.v_normal) * _892.z));
        break;
    } while(false);
    half _941 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _951 = dfdx(float3(_2104));
    float3 _953 = dfdy(float3(_2104));
    half _964 = _941 * _941;
    half _1040 = clamp(half(sqrt(sqrt(fast::min(fma(float(_964), float(_964), fast::min((dot(_951, _951) + dot(_953, _953)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1013 = max(dot(_2104, half3(_734)), half(9.9999997473787516355514526367188e-05));
    float4 _1047 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1013, _1040)), level(0.0));
    float4 _1066 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_734), _2104)), level(_1040 * (half(4.0) * (half(2.0) - _1040))));
    half _1170 = _1040 * _1040;
    float3 _1182 = fast::normalize(_734 + frame.lightDirection.xyz);
    half _1124 = clamp(dot(_2104, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1222 = half(4096.0) * _1170;
    half4 _1247 = half4(cross(_2104, half3(_1182)), _1170 * clamp(dot(_2104, half3(_1182)), half(0.0), half(1.0))) * half(64.0);
    half _1228 = _1222 / dot(_1247, _1247);
    half _1258 = _1170 * _1170;
    half _1264 = fma(half(-float(_1170)), _1170, half(1.0));
    half _1268 = sqrt(fma(_1013 * _1013, _1264, _1258));
    half _1292 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1182)), half(0.0), half(1.0));
    half _1295 = _1292 * _1292;
    half3 _1303 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1347 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1350 = dot(_1347, _1347);
    float3 _1355 = _1347 * rsqrt(fast::max(_1350, 9.9999999392252902907785028219223e-09));
    float _1359 = _1350 * float(frame.punctualLights[0].positionFalloff.w);
    float _1364 = fast::clamp(fma(-_1359, _1359, 1.0), 0.0, 1.0);
    float _1383 = fast::clamp(fma(dot(-_1355, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1502 = fast::normalize(_734 + _1355);
    half _1444 = clamp(dot(_2104, half3(_1355)), half(0.0), half(1.0));
    half4 _1567 = half4(cross(_2104, half3(_1502)), _1170 * clamp(dot(_2104, half3(_1502)), half(0.0), half(1.0))) * half(64.0);
    half _1548 = _1222 / dot(_1567, _1567);
    half _1612 = half(1.0) - clamp(dot(half3(_1355), half3(_1502)), half(0.0), half(1.0));
    half _1615 = _1612 * _1612;
    float3 _1667 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1670 = dot(_1667, _1667);
    float3 _1675 = _1667 * rsqrt(fast::max(_1670, 9.9999999392252902907785028219223e-09));
    float _1679 = _1670 * float(frame.punctualLights[1].positionFalloff.w);
    float _1684 = fast::clamp(fma(-_1679, _1679, 1.0), 0.0, 1.0);
    float _1703 = fast::clamp(fma(dot(-_1675, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1822 = fast::normalize(_734 + _1675);
    half _1764 = clamp(dot(_2104, half3(_1675)), half(0.0), half(1.0));
    half4 _1887 = half4(cross(_2104, half3(_1822)), _1170 * clamp(dot(_2104, half3(_1822)), half(0.0), half(1.0))) * half(64.0);
    half _1868 = _1222 / dot(_1887, _1887);
    half _1932 = half(1.0) - clamp(dot(half3(_1675), half3(_1822)), half(0.0), half(1.0));
    half _1935 = _1932 * _1932;
    half3 _1951 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1066).xyz * mix(half4(_1047).xxx, half4(_1047).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + (_1303 * ((_1295 * _1295) * _1292))) * min(min((_1228 * _1228) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1124, _1268, _1013 * sqrt(fma(_1124 * _1124, _1264, _1258))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1124), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1303 * ((_1615 * _1615) * _1612))) * min(min((_1548 * _1548) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1444, _1268, _1013 * sqrt(fma(_1444 * _1444, _1264, _1258))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1364) * half(_1364)) / fast::max(_1350, 9.9999997473787516355514526367188e-05)) * half(_1383)) * half(_1383)), float3(65504.0))) * _1444), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1303 * ((_1935 * _1935) * _1932))) * min(min((_1868 * _1868) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1764, _1268, _1013 * sqrt(fma(_1764 * _1764, _1264, _1258))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1684) * half(_1684)) / fast::max(_1670, 9.9999997473787516355514526367188e-05)) * half(_1703)) * half(_1703)), float3(65504.0))) * _1764), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1951, half(1.0)));
    return out;
}

