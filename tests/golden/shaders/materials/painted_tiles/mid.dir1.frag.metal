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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _629 = fast::normalize(in.v_toEye);
    float2 _761 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _764 = facet_material_albedo.sample(facet_material_albedoSmplr, _761);
    float4 _774 = facet_material_relief.sample(facet_material_reliefSmplr, _761);
    half3 _778 = (half4(_774).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _784 = fract(_761 * 4.0);
    float _786 = _784.x;
    float _793 = _784.y;
    half3 _1286;
    do
    {
        half3 _818 = half4(in.v_tangent).xyz;
        if (float(dot(_818, _818)) == 0.0)
        {
            _1286 = normalize(half3(in.v_normal));
            break;
        }
        _1286 = normalize(((_818 * _778.x) + ((cross(half3(in.v_normal), _818) * half(in.v_tangent.w)) * _778.y)) + (half3(in.v_normal) * _778.z));
        break;
    } while(false);
    half _867 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_786, 1.0 - _786), fast::min(_793, 1.0 - _793))))), half(0.0), half(1.0));
    half _902 = max(dot(_1286, half3(_629)), half(9.9999997473787516355514526367188e-05));
    float4 _967 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_902, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _986 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_967).y) - half(1.0)));
    float4 _993 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_629), _1286)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _680 = half4(frame.lightDirection).xyz;
    half3 _1130 = normalize(half3(_629) + _680);
    half _1057 = clamp(dot(_1286, _680), half(0.0), half(1.0));
    half3 _1157 = cross(_1286, _1130);
    half _1160 = clamp(dot(_1286, _1130), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1177 = max(mix((half(2.0) * _1057) * _902, _1057 + _902, half(params.facet_alpha)), half(0.000244140625));
    half _1184 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1160, _1160, dot(_1157, _1157)) * (half(6433.98193359375) * _1177));
    out.fragColor = float4(half4(((((clamp(half4(_764).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0)) * half3(in.v_diffuseLight)) * _867) + ((half4(_993).xyz * (mix(half4(_967).xxx, half4(_967).yyy, half3(float3(0.039999999105930328369140625))) * _986)) * _867)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1184 * (_1184 * (half(6.283185482025146484375) * _1177)), half(65504.0))) * _986) * (half4(frame.lightColor).xyz * _1057), half3(float3(65504.0))), half(1.0)));
    return out;
}

