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
    half3 _826 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float2 _866 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _869 = facet_material_albedo.sample(facet_material_albedoSmplr, _866);
    float4 _879 = facet_material_relief.sample(facet_material_reliefSmplr, _866);
    half3 _883 = (half4(_879).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _889 = fract(_866 * 4.0);
    float _891 = _889.x;
    float _898 = _889.y;
    half3 _1474;
    do
    {
        half3 _923 = half4(in.v_tangent).xyz;
        if (float(dot(_923, _923)) == 0.0)
        {
            _1474 = normalize(half3(in.v_normal));
            break;
        }
        _1474 = normalize(((_923 * _883.x) + ((cross(half3(in.v_normal), _923) * half(in.v_tangent.w)) * _883.y)) + (half3(in.v_normal) * _883.z));
        break;
    } while(false);
    half3 _966 = clamp(half4(_869).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _975 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_891, 1.0 - _891), fast::min(_898, 1.0 - _898))))), half(0.0), half(1.0));
    half _1068 = max(dot(_1474, _826), half(9.9999997473787516355514526367188e-05));
    float4 _1133 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1068, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1152 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1133).y) - half(1.0)));
    float4 _1162 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_826, _1474)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _775 = half4(frame.lightDirection).xyz;
    half3 _1299 = normalize(_826 + _775);
    half _1226 = clamp(dot(_1474, _775), half(0.0), half(1.0));
    half4 _1368 = half4(cross(_1474, _1299), half(params.facet_alpha) * clamp(dot(_1474, _1299), half(0.0), half(1.0))) * half(64.0);
    half _1345 = half(6.283185482025146484375) * max(mix((half(2.0) * _1226) * _1068, _1226 + _1068, half(params.facet_alpha)), half(0.000244140625));
    half _1347 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1368, _1368) * _1345);
    half3 _1376 = (fma(_966 * half3(in.v_diffuseLight), max(half3(_975), ((((((_966 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _975) + ((_966 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _975) + ((_966 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _975), _966 * half3(in.v_directDiffuse)) + ((half4(_1162).xyz * (mix(half4(_1133).xxx, half4(_1133).yyy, half3(float3(0.039999999105930328369140625))) * _1152)) * _975)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1347 * (_1347 * _1345), half(65504.0))) * _1152) * (half4(frame.lightColor).xyz * _1226), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1376, half(1.0)));
    return out;
}

