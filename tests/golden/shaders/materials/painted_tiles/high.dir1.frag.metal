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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _749 = fast::normalize(in.v_toEye);
    float2 _878 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _881 = facet_material_albedo.sample(facet_material_albedoSmplr, _878);
    float4 _891 = facet_material_relief.sample(facet_material_reliefSmplr, _878);
    half3 _895 = (half4(_891).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _901 = fract(_878 * 4.0);
    float _903 = _901.x;
    float _910 = _901.y;
    half3 _1521;
    do
    {
        half3 _935 = half4(in.v_tangent).xyz;
        if (float(dot(_935, _935)) == 0.0)
        {
            _1521 = normalize(half3(in.v_normal));
            break;
        }
        _1521 = normalize(((_935 * _895.x) + ((cross(half3(in.v_normal), _935) * half(in.v_tangent.w)) * _895.y)) + (half3(in.v_normal) * _895.z));
        break;
    } while(false);
    float4 _971 = facet_irradiance.sample(facet_irradianceSmplr, float3(_1521), level(0.0));
    half3 _995 = clamp(half4(_881).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1004 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_903, 1.0 - _903), fast::min(_910, 1.0 - _910))))), half(0.0), half(1.0));
    half _1083 = max(dot(_1521, half3(_749)), half(9.9999997473787516355514526367188e-05));
    float4 _1142 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1083, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1161 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_749), _1521)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1304 = fast::normalize(_749 + frame.lightDirection.xyz);
    half _1227 = clamp(dot(_1521, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1369 = half4(cross(_1521, half3(_1304)), half(params.facet_alpha) * clamp(dot(_1521, half3(_1304)), half(0.0), half(1.0))) * half(64.0);
    half _1350 = (half(4096.0) * half(params.facet_alpha)) / dot(_1369, _1369);
    half _1394 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1304)), half(0.0), half(1.0));
    half _1397 = _1394 * _1394;
    half3 _1427 = fma(_995 * half4(_971).xyz, max(half3(_1004), ((((((_995 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1004) + ((_995 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1004) + ((_995 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1004), (half4(_1161).xyz * mix(half4(_1142).xxx, half4(_1142).yyy, half3(float3(0.039999999105930328369140625)))) * _1004) + min(((_995 * half(0.3183098733425140380859375)) + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1397 * _1397) * _1394))) * min(min((_1350 * _1350) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1227) * _1083, _1227 + _1083, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _1227), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1427, half(1.0)));
    return out;
}

