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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _774 = fast::normalize(in.v_toEye);
    float4 _888 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _892 = (half4(_888).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1570;
    do
    {
        half3 _905 = half4(in.v_tangent).xyz;
        if (float(dot(_905, _905)) == 0.0)
        {
            _1570 = normalize(half3(in.v_normal));
            break;
        }
        _1570 = normalize(((_905 * _892.x) + ((cross(half3(in.v_normal), _905) * half(in.v_tangent.w)) * _892.y)) + (half3(in.v_normal) * _892.z));
        break;
    } while(false);
    half _941 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _951 = dfdx(float3(_1570));
    float3 _953 = dfdy(float3(_1570));
    half _964 = _941 * _941;
    half3 _1082 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1570.y)) + (half4(frame.sh[2]).xyz * _1570.z)) + (half4(frame.sh[3]).xyz * _1570.x)) + (((((half4(frame.sh[4]).xyz * (_1570.x * _1570.y)) + (half4(frame.sh[5]).xyz * (_1570.y * _1570.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1570.z, _1570.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1570.x * _1570.z))) + (half4(frame.sh[8]).xyz * fma(_1570.x, _1570.x, half(-float(_1570.y * _1570.y))))), half3(float3(0.0)));
    half _1165 = clamp(half(sqrt(sqrt(fast::min(fma(float(_964), float(_964), fast::min((dot(_951, _951) + dot(_953, _953)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1132 = max(dot(_1570, half3(_774)), half(9.9999997473787516355514526367188e-05));
    float4 _1172 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1132, _1165)), level(0.0));
    half3 _1191 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1172).y) - half(1.0)));
    float4 _1198 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_774), _1570)), level(_1165 * half(4.0)));
    half _1313 = _1165 * _1165;
    float3 _1325 = fast::normalize(_774 + frame.lightDirection.xyz);
    half _1258 = clamp(dot(_1570, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1365 = cross(_1570, half3(_1325));
    half _1368 = clamp(dot(_1570, half3(_1325)), half(0.0), half(1.0)) * _1313;
    half _1377 = _1313 / fma(_1368, _1368, dot(_1365, _1365));
    half _1391 = _1313 * _1313;
    half _1397 = fma(half(-float(_1313)), _1313, half(1.0));
    half _1425 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1325)), half(0.0), half(1.0));
    half _1428 = _1425 * _1425;
    half3 _1450 = fma(half3(float3(params.facet_diffuseColor)), _1082, half4(_1198).xyz * (mix(half4(_1172).xxx, half4(_1172).yyy, half3(float3(params.facet_f0))) * _1191)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1428 * _1428) * _1425))) * min(min((_1377 * _1377) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1258, sqrt(fma(_1132 * _1132, _1397, _1391)), _1132 * sqrt(fma(_1258 * _1258, _1397, _1391))), half(65504.0)), half(65504.0)), _1191, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1258), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1450, half(1.0)));
    return out;
}

