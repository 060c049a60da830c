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
    float3 _503 = fast::normalize(in.v_toEye);
    float4 _596 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _600 = (half4(_596).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1033;
    do
    {
        half3 _613 = half4(in.v_tangent).xyz;
        if (float(dot(_613, _613)) == 0.0)
        {
            _1033 = normalize(half3(in.v_normal));
            break;
        }
        _1033 = normalize(((_613 * _600.x) + ((cross(half3(in.v_normal), _613) * half(in.v_tangent.w)) * _600.y)) + (half3(in.v_normal) * _600.z));
        break;
    } while(false);
    half _649 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _659 = dfdx(float3(_1033));
    float3 _661 = dfdy(float3(_1033));
    half _672 = _649 * _649;
    half3 _790 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1033.y)) + (half4(frame.sh[2]).xyz * _1033.z)) + (half4(frame.sh[3]).xyz * _1033.x)) + (((((half4(frame.sh[4]).xyz * (_1033.x * _1033.y)) + (half4(frame.sh[5]).xyz * (_1033.y * _1033.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1033.z, _1033.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1033.x * _1033.z))) + (half4(frame.sh[8]).xyz * fma(_1033.x, _1033.x, half(-float(_1033.y * _1033.y))))), half3(float3(0.0)));
    half _873 = clamp(half(sqrt(sqrt(fast::min(fma(float(_672), float(_672), fast::min((dot(_659, _659) + dot(_661, _661)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    float4 _880 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1033, half3(_503)), half(9.9999997473787516355514526367188e-05)), _873)), level(0.0));
    float4 _906 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_503), _1033)), level(_873 * half(4.0)));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), _790, half4(_906).xyz * (mix(half4(_880).xxx, half4(_880).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_880).y) - half(1.0)))))), half(1.0)));
    return out;
}

