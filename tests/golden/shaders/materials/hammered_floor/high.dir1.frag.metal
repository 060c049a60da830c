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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_relief [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_reliefSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _772 = fast::normalize(in.v_toEye);
    float4 _886 = facet_material_relief.sample(facet_material_reliefSmplr, (in.v_uv0 * params.tiling));
    half3 _890 = (half4(_886).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1566;
    do
    {
        half3 _903 = half4(in.v_tangent).xyz;
        if (float(dot(_903, _903)) == 0.0)
        {
            _1566 = normalize(half3(in.v_normal));
            break;
        }
        _1566 = normalize(((_903 * _890.x) + ((cross(half3(in.v_normal), _903) * half(in.v_tangent.w)) * _890.y)) + (half3(in.v_normal) * _890.z));
        break;
    } while(false);
    half _939 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _948 = dfdx(float3(_1566));
    float3 _950 = dfdy(float3(_1566));
    half _961 = _939 * _939;
    half3 _1078 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1566.y)) + (half4(frame.sh[2]).xyz * _1566.z)) + (half4(frame.sh[3]).xyz * _1566.x)) + (((((half4(frame.sh[4]).xyz * (_1566.x * _1566.y)) + (half4(frame.sh[5]).xyz * (_1566.y * _1566.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1566.z, _1566.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1566.x * _1566.z))) + (half4(frame.sh[8]).xyz * fma(_1566.x, _1566.x, half(-float(_1566.y * _1566.y))))), half3(float3(0.0)));
    half _1161 = clamp(sqrt(sqrt(min(fma(_961, _961, min((dot(half3(_948), half3(_948)) + dot(half3(_950), half3(_950))) * half(0.300000011920928955078125), half(0.20000000298023223876953125))), half(1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1128 = max(dot(_1566, half3(_772)), half(9.9999997473787516355514526367188e-05));
    float4 _1168 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1128, _1161)), level(0.0));
    half3 _1187 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1168).y) - half(1.0)));
    float4 _1194 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_772), _1566)), level(_1161 * half(4.0)));
    half _1309 = _1161 * _1161;
    float3 _1321 = fast::normalize(_772 + frame.lightDirection.xyz);
    half _1254 = clamp(dot(_1566, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1361 = cross(_1566, half3(_1321));
    half _1364 = clamp(dot(_1566, half3(_1321)), half(0.0), half(1.0)) * _1309;
    half _1373 = _1309 / fma(_1364, _1364, dot(_1361, _1361));
    half _1387 = _1309 * _1309;
    half _1393 = fma(half(-float(_1309)), _1309, half(1.0));
    half _1421 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1321)), half(0.0), half(1.0));
    half _1424 = _1421 * _1421;
    half3 _1446 = fma(half3(float3(params.facet_diffuseColor)), _1078, half4(_1194).xyz * (mix(half4(_1168).xxx, half4(_1168).yyy, half3(float3(params.facet_f0))) * _1187)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1424 * _1424) * _1421))) * min(min((_1373 * _1373) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1254, sqrt(fma(_1128 * _1128, _1393, _1387)), _1128 * sqrt(fma(_1254 * _1254, _1393, _1387))), half(65504.0)), half(65504.0)), _1187, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1254), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1446, half(1.0)));
    return out;
}

