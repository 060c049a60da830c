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
    float3 _506 = fast::normalize(in.v_toEye);
    float4 _599 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _603 = (half4(_599).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1039;
    do
    {
        half3 _616 = half4(in.v_tangent).xyz;
        if (float(dot(_616, _616)) == 0.0)
        {
            _1039 = normalize(half3(in.v_normal));
            break;
        }
        _1039 = normalize(((_616 * _603.x) + ((cross(half3(in.v_normal), _616) * half(in.v_tangent.w)) * _603.y)) + (half3(in.v_normal) * _603.z));
        break;
    } while(false);
    half _652 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _662 = dfdx(float3(_1039));
    float3 _664 = dfdy(float3(_1039));
    half _675 = _652 * _652;
    half3 _793 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1039.y)) + (half4(frame.sh[2]).xyz * _1039.z)) + (half4(frame.sh[3]).xyz * _1039.x)) + (((((half4(frame.sh[4]).xyz * (_1039.x * _1039.y)) + (half4(frame.sh[5]).xyz * (_1039.y * _1039.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1039.z, _1039.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1039.x * _1039.z))) + (half4(frame.sh[8]).xyz * fma(_1039.x, _1039.x, half(-float(_1039.y * _1039.y))))), half3(float3(0.0)));
    half _876 = clamp(half(sqrt(sqrt(fast::min(fma(float(_675), float(_675), fast::min((dot(_662, _662) + dot(_664, _664)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    float4 _883 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1039, half3(_506)), half(9.9999997473787516355514526367188e-05)), _876)), level(0.0));
    float4 _912 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_506), _1039)), level(_876 * (half(4.0) * (half(2.0) - _876))));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), _793, half4(_912).xyz * (mix(half4(_883).xxx, half4(_883).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_883).y) - half(1.0)))))), half(1.0)));
    return out;
}

