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
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _675 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _829 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _833 = (half4(_829).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1886;
    do
    {
        half3 _846 = half4(in.v_tangent).xyz;
        if (float(dot(_846, _846)) == 0.0)
        {
            _1886 = normalize(half3(in.v_normal));
            break;
        }
        _1886 = normalize(((_846 * _833.x) + ((cross(half3(in.v_normal), _846) * half(in.v_tangent.w)) * _833.y)) + (half3(in.v_normal) * _833.z));
        break;
    } while(false);
    half _882 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _892 = dfdx(float3(_1886));
    float3 _894 = dfdy(float3(_1886));
    half _905 = _882 * _882;
    half _981 = clamp(half(sqrt(sqrt(fast::min(fma(float(_905), float(_905), fast::min((dot(_892, _892) + dot(_894, _894)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _954 = max(dot(_1886, half3(_675)), half(9.9999997473787516355514526367188e-05));
    float4 _988 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_954, _981)), level(0.0));
    float4 _1007 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_675), _1886)), level(_981 * (half(4.0) * (half(2.0) - _981))));
    half3 _724 = half4(frame.lightDirection).xyz;
    half _1111 = _981 * _981;
    half _1062 = clamp(dot(_1886, _724), half(0.0), half(1.0));
    half3 _1122 = normalize(half3(_675) + _724);
    half4 _1191 = half4(cross(_1886, _1122), _1111 * clamp(dot(_1886, _1122), half(0.0), half(1.0))) * half(64.0);
    half _1165 = half(4096.0) * _1111;
    half _1168 = half(6.283185482025146484375) * max(mix((half(2.0) * _1062) * _954, _1062 + _954, _1111), half(0.000244140625));
    half _1170 = _1165 / (dot(_1191, _1191) * _1168);
    float3 _1235 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1238 = dot(_1235, _1235);
    float3 _1243 = _1235 * rsqrt(fast::max(_1238, 9.9999999392252902907785028219223e-09));
    float _1247 = _1238 * float(frame.punctualLights[0].positionFalloff.w);
    float _1252 = fast::clamp(fma(-_1247, _1247, 1.0), 0.0, 1.0);
    float _1271 = fast::clamp(fma(dot(-_1243, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1329 = clamp(dot(_1886, half3(_1243)), half(0.0), half(1.0));
    half3 _1389 = normalize(half3(_675) + half3(_1243));
    half4 _1458 = half4(cross(_1886, _1389), _1111 * clamp(dot(_1886, _1389), half(0.0), half(1.0))) * half(64.0);
    half _1435 = half(6.283185482025146484375) * max(mix((half(2.0) * _1329) * _954, _1329 + _954, _1111), half(0.000244140625));
    half _1437 = _1165 / (dot(_1458, _1458) * _1435);
    float3 _1502 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1505 = dot(_1502, _1502);
    float3 _1510 = _1502 * rsqrt(fast::max(_1505, 9.9999999392252902907785028219223e-09));
    float _1514 = _1505 * float(frame.punctualLights[1].positionFalloff.w);
    float _1519 = fast::clamp(fma(-_1514, _1514, 1.0), 0.0, 1.0);
    float _1538 = fast::clamp(fma(dot(-_1510, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1596 = clamp(dot(_1886, half3(_1510)), half(0.0), half(1.0));
    half3 _1656 = normalize(half3(_675) + half3(_1510));
    half4 _1725 = half4(cross(_1886, _1656), _1111 * clamp(dot(_1886, _1656), half(0.0), half(1.0))) * half(64.0);
    half _1702 = half(6.283185482025146484375) * max(mix((half(2.0) * _1596) * _954, _1596 + _954, _1111), half(0.000244140625));
    half _1704 = _1165 / (dot(_1725, _1725) * _1702);
    half3 _1733 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1007).xyz * mix(half4(_988).xxx, half4(_988).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min(_1170 * (_1170 * _1168), half(65504.0))) * (half4(frame.lightColor).xyz * _1062), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min(_1437 * (_1437 * _1435), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1252) * half(_1252)) / fast::max(_1238, 9.9999997473787516355514526367188e-05)) * half(_1271)) * half(_1271)), float3(65504.0))) * _1329), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min(_1704 * (_1704 * _1702), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1519) * half(_1519)) / fast::max(_1505, 9.9999997473787516355514526367188e-05)) * half(_1538)) * half(_1538)), float3(65504.0))) * _1596), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1733, half(1.0)));
    return out;
}

