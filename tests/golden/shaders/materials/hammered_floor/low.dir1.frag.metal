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
    float3 v_diffuseLight [[user(locn4)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _530 = fast::normalize(in.v_toEye);
    float4 _660 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _664 = (half4(_660).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1107;
    do
    {
        half3 _677 = half4(in.v_tangent).xyz;
        if (float(dot(_677, _677)) == 0.0)
        {
            _1107 = normalize(half3(in.v_normal));
            break;
        }
        _1107 = normalize(((_677 * _664.x) + ((cross(half3(in.v_normal), _677) * half(in.v_tangent.w)) * _664.y)) + (half3(in.v_normal) * _664.z));
        break;
    } while(false);
    half _713 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _723 = dfdx(float3(_1107));
    float3 _725 = dfdy(float3(_1107));
    half _736 = _713 * _713;
    half _813 = clamp(half(sqrt(sqrt(fast::min(fma(float(_736), float(_736), fast::min((dot(_723, _723) + dot(_725, _725)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half3 _789 = reflect(-half3(_530), _1107);
    float4 _820 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1107, half3(_530)), half(9.9999997473787516355514526367188e-05)), _813)), level(0.0));
    half3 _829 = mix(half4(_820).xxx, half4(_820).yyy, half3(float3(params.facet_f0)));
    float4 _839 = facet_environment.sample(facet_environmentSmplr, float3(_789), level(_813 * (half(4.0) * (half(2.0) - _813))));
    half3 _589 = half4(frame.lightDirection).xyz;
    half _979 = clamp(dot(_789, _589), half(0.0), half(1.0));
    half _982 = _979 * _979;
    half4 _1163 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_982 * _982, _813), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _994 = _1163.x;
    half3 _1003 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_839).xyz * _829) + min((_829 * ((_994 * _994) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1107, _589), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1003, half(1.0)));
    return out;
}

