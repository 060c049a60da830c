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
    float3 v_diffuseLight [[user(locn4)]];
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _677 = fast::normalize(in.v_toEye);
    float2 _821 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _824 = facet_material_albedo.sample(facet_material_albedoSmplr, _821);
    float4 _834 = facet_material_relief.sample(facet_material_reliefSmplr, _821);
    half3 _838 = (half4(_834).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _844 = fract(_821 * 4.0);
    float _846 = _844.x;
    float _853 = _844.y;
    half3 _1415;
    do
    {
        half3 _878 = half4(in.v_tangent).xyz;
        if (float(dot(_878, _878)) == 0.0)
        {
            _1415 = normalize(half3(in.v_normal));
            break;
        }
        _1415 = normalize(((_878 * _838.x) + ((cross(half3(in.v_normal), _878) * half(in.v_tangent.w)) * _838.y)) + (half3(in.v_normal) * _838.z));
        break;
    } while(false);
    half3 _921 = clamp(half4(_824).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _930 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_846, 1.0 - _846), fast::min(_853, 1.0 - _853))))), half(0.0), half(1.0));
    half _1023 = max(dot(_1415, half3(_677)), half(9.9999997473787516355514526367188e-05));
    float4 _1088 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1023, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1107 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1088).y) - half(1.0)));
    float4 _1114 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_677), _1415)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _740 = half4(frame.lightDirection).xyz;
    half3 _1251 = normalize(half3(_677) + _740);
    half _1178 = clamp(dot(_1415, _740), half(0.0), half(1.0));
    half3 _1278 = cross(_1415, _1251);
    half _1281 = clamp(dot(_1415, _1251), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1298 = max(mix((half(2.0) * _1178) * _1023, _1178 + _1023, half(params.facet_alpha)), half(0.000244140625));
    half _1305 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1281, _1281, dot(_1278, _1278)) * (half(6433.98193359375) * _1298));
    half3 _1317 = (fma(_921 * half3(in.v_diffuseLight), max(half3(_930), ((((((_921 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _930) + ((_921 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _930) + ((_921 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _930), _921 * half3(in.v_directDiffuse)) + ((half4(_1114).xyz * (mix(half4(_1088).xxx, half4(_1088).yyy, half3(float3(0.039999999105930328369140625))) * _1107)) * _930)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1305 * (_1305 * (half(6.283185482025146484375) * _1298)), half(65504.0))) * _1107) * (half4(frame.lightColor).xyz * _1178), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1317, half(1.0)));
    return out;
}

