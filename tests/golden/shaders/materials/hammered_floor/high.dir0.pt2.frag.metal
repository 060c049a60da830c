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
    float4 _867 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _871 = (half4(_867).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1845;
    do
    {
        half3 _884 = half4(in.v_tangent).xyz;
        if (float(dot(_884, _884)) == 0.0)
        {
            _1845 = normalize(half3(in.v_normal));
            break;
        }
        _1845 = normalize(((_884 * _871.x) + ((cross(half3(in.v_normal), _884) * half(in.v_tangent.w)) * _871.y)) + (half3(in.v_normal) * _871.z));
        break;
    } while(false);
    half _920 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _930 = dfdx(float3(_1845));
    float3 _932 = dfdy(float3(_1845));
    half _943 = _920 * _920;
    half _1019 = clamp(half(sqrt(sqrt(fast::min(fma(float(_943), float(_943), fast::min((dot(_930, _930) + dot(_932, _932)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _992 = max(dot(_1845, half3(_734)), half(9.9999997473787516355514526367188e-05));
    float4 _1026 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_992, _1019)), level(0.0));
    float4 _1045 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_734), _1845)), level(_1019 * (half(4.0) * (half(2.0) - _1019))));
    float3 _1090 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1093 = dot(_1090, _1090);
    float3 _1098 = _1090 * rsqrt(fast::max(_1093, 9.9999999392252902907785028219223e-09));
    float _1102 = _1093 * float(frame.punctualLights[0].positionFalloff.w);
    float _1107 = fast::clamp(fma(-_1102, _1102, 1.0), 0.0, 1.0);
    float _1126 = fast::clamp(fma(dot(-_1098, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1233 = _1019 * _1019;
    float3 _1245 = fast::normalize(_734 + _1098);
    half _1187 = clamp(dot(_1845, half3(_1098)), half(0.0), half(1.0));
    half _1285 = half(4096.0) * _1233;
    half4 _1310 = half4(cross(_1845, half3(_1245)), _1233 * clamp(dot(_1845, half3(_1245)), half(0.0), half(1.0))) * half(64.0);
    half _1291 = _1285 / dot(_1310, _1310);
    half _1321 = _1233 * _1233;
    half _1327 = fma(half(-float(_1233)), _1233, half(1.0));
    half _1331 = sqrt(fma(_992 * _992, _1327, _1321));
    half _1355 = half(1.0) - clamp(dot(half3(_1098), half3(_1245)), half(0.0), half(1.0));
    half _1358 = _1355 * _1355;
    half3 _1366 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1410 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1413 = dot(_1410, _1410);
    float3 _1418 = _1410 * rsqrt(fast::max(_1413, 9.9999999392252902907785028219223e-09));
    float _1422 = _1413 * float(frame.punctualLights[1].positionFalloff.w);
    float _1427 = fast::clamp(fma(-_1422, _1422, 1.0), 0.0, 1.0);
    float _1446 = fast::clamp(fma(dot(-_1418, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1565 = fast::normalize(_734 + _1418);
    half _1507 = clamp(dot(_1845, half3(_1418)), half(0.0), half(1.0));
    half4 _1630 = half4(cross(_1845, half3(_1565)), _1233 * clamp(dot(_1845, half3(_1565)), half(0.0), half(1.0))) * half(64.0);
    half _1611 = _1285 / dot(_1630, _1630);
    half _1675 = half(1.0) - clamp(dot(half3(_1418), half3(_1565)), half(0.0), half(1.0));
    half _1678 = _1675 * _1675;
    half3 _1694 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1045).xyz * mix(half4(_1026).xxx, half4(_1026).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + (_1366 * ((_1358 * _1358) * _1355))) * min(min((_1291 * _1291) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1187, _1331, _992 * sqrt(fma(_1187 * _1187, _1327, _1321))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1107) * half(_1107)) / fast::max(_1093, 9.9999997473787516355514526367188e-05)) * half(_1126)) * half(_1126)), float3(65504.0))) * _1187), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1366 * ((_1678 * _1678) * _1675))) * min(min((_1611 * _1611) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1507, _1331, _992 * sqrt(fma(_1507 * _1507, _1327, _1321))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1427) * half(_1427)) / fast::max(_1413, 9.9999997473787516355514526367188e-05)) * half(_1446)) * half(_1446)), float3(65504.0))) * _1507), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1694, half(1.0)));
    return out;
}

