#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float tiling;
    float roughness;
    float facet_pad8;
    float facet_pad12;
    float facet_perceptualRoughness;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _773 = fast::normalize(in.v_toEye);
    float2 _881 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _884 = facet_material_albedo.sample(facet_material_albedoSmplr, _881);
    float4 _894 = facet_material_relief.sample(facet_material_reliefSmplr, _881);
    half3 _898 = (half4(_894).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1565;
    do
    {
        half3 _911 = half4(in.v_tangent).xyz;
        if (float(dot(_911, _911)) == 0.0)
        {
            _1565 = normalize(half3(in.v_normal));
            break;
        }
        _1565 = normalize(((_911 * _898.x) + ((cross(half3(in.v_normal), _911) * half(in.v_tangent.w)) * _898.y)) + (half3(in.v_normal) * _898.z));
        break;
    } while(false);
    half3 _1048 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1565.y)) + (half4(frame.sh[2]).xyz * _1565.z)) + (half4(frame.sh[3]).xyz * _1565.x)) + (((((half4(frame.sh[4]).xyz * (_1565.x * _1565.y)) + (half4(frame.sh[5]).xyz * (_1565.y * _1565.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1565.z, _1565.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1565.x * _1565.z))) + (half4(frame.sh[8]).xyz * fma(_1565.x, _1565.x, half(-float(_1565.y * _1565.y))))), half3(float3(0.0)));
    half3 _1071 = clamp(half4(_884).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1106 = max(dot(_1565, half3(_773)), half(9.9999997473787516355514526367188e-05));
    float4 _1169 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1106, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1188 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1169).y) - half(1.0)));
    float4 _1195 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_773), _1565)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1335 = fast::normalize(_773 + frame.lightDirection.xyz);
    half _1255 = clamp(dot(_1565, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1375 = cross(_1565, half3(_1335));
    half _1378 = clamp(dot(_1565, half3(_1335)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1387 = half(params.facet_alpha) / fma(_1378, _1378, dot(_1375, _1375));
    half _1401 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1407 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1435 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1335)), half(0.0), half(1.0));
    half _1438 = _1435 * _1435;
    half3 _1468 = fma(_1071, _1048, half4(_1195).xyz * (mix(half4(_1169).xxx, half4(_1169).yyy, half3(float3(0.039999999105930328369140625))) * _1188)) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1438 * _1438) * _1435))) * min(min((_1387 * _1387) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1255, sqrt(fma(_1106 * _1106, _1407, _1401)), _1106 * sqrt(fma(_1255 * _1255, _1407, _1401))), half(65504.0)), half(65504.0)), _1188, _1071 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1255), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1468, half(1.0)));
    return out;
}

