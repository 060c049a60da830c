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
    float3 _682 = fast::normalize(in.v_toEye);
    float2 _826 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _829 = facet_material_albedo.sample(facet_material_albedoSmplr, _826);
    float4 _839 = facet_material_relief.sample(facet_material_reliefSmplr, _826);
    half3 _843 = (half4(_839).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _849 = fract(_826 * 4.0);
    float _851 = _849.x;
    float _858 = _849.y;
    half3 _1425;
    do
    {
        half3 _883 = half4(in.v_tangent).xyz;
        if (float(dot(_883, _883)) == 0.0)
        {
            _1425 = normalize(half3(in.v_normal));
            break;
        }
        _1425 = normalize(((_883 * _843.x) + ((cross(half3(in.v_normal), _883) * half(in.v_tangent.w)) * _843.y)) + (half3(in.v_normal) * _843.z));
        break;
    } while(false);
    half3 _926 = clamp(half4(_829).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _935 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_851, 1.0 - _851), fast::min(_858, 1.0 - _858))))), half(0.0), half(1.0));
    half _1028 = max(dot(_1425, half3(_682)), half(9.9999997473787516355514526367188e-05));
    float4 _1093 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1028, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1112 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1093).y) - half(1.0)));
    float4 _1124 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_682), _1425)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _745 = half4(frame.lightDirection).xyz;
    half3 _1261 = normalize(half3(_682) + _745);
    half _1188 = clamp(dot(_1425, _745), half(0.0), half(1.0));
    half3 _1288 = cross(_1425, _1261);
    half _1291 = clamp(dot(_1425, _1261), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1308 = max(mix((half(2.0) * _1188) * _1028, _1188 + _1028, half(params.facet_alpha)), half(0.000244140625));
    half _1315 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1291, _1291, dot(_1288, _1288)) * (half(6433.98193359375) * _1308));
    half3 _1327 = (fma(_926 * half3(in.v_diffuseLight), max(half3(_935), ((((((_926 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _935) + ((_926 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _935) + ((_926 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _935), _926 * half3(in.v_directDiffuse)) + ((half4(_1124).xyz * (mix(half4(_1093).xxx, half4(_1093).yyy, half3(float3(0.039999999105930328369140625))) * _1112)) * _935)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1315 * (_1315 * (half(6.283185482025146484375) * _1308)), half(65504.0))) * _1112) * (half4(frame.lightColor).xyz * _1188), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1327, half(1.0)));
    return out;
}

