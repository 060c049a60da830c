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
    float3 _657 = fast::normalize(in.v_toEye);
    float2 _755 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _758 = facet_material_albedo.sample(facet_material_albedoSmplr, _755);
    float4 _768 = facet_material_relief.sample(facet_material_reliefSmplr, _755);
    half3 _772 = (half4(_768).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _778 = fract(_755 * 4.0);
    float _780 = _778.x;
    float _787 = _778.y;
    half3 _1299;
    do
    {
        half3 _812 = half4(in.v_tangent).xyz;
        if (float(dot(_812, _812)) == 0.0)
        {
            _1299 = normalize(half3(in.v_normal));
            break;
        }
        _1299 = normalize(((_812 * _772.x) + ((cross(half3(in.v_normal), _812) * half(in.v_tangent.w)) * _772.y)) + (half3(in.v_normal) * _772.z));
        break;
    } while(false);
    half3 _949 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1299.y)) + (half4(frame.sh[2]).xyz * _1299.z)) + (half4(frame.sh[3]).xyz * _1299.x)) + (((((half4(frame.sh[4]).xyz * (_1299.x * _1299.y)) + (half4(frame.sh[5]).xyz * (_1299.y * _1299.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1299.z, _1299.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1299.x * _1299.z))) + (half4(frame.sh[8]).xyz * fma(_1299.x, _1299.x, half(-float(_1299.y * _1299.y))))), half3(float3(0.0)));
    half3 _972 = clamp(half4(_758).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _981 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_780, 1.0 - _780), fast::min(_787, 1.0 - _787))))), half(0.0), half(1.0));
    half _1062 = max(dot(_1299, half3(_657)), half(9.9999997473787516355514526367188e-05));
    float4 _1127 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1062, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1158 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_657), _1299)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1199 = fma(_972 * _949, max(half3(_981), ((((((_972 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _981) + ((_972 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _981) + ((_972 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _981), (half4(_1158).xyz * (mix(half4(_1127).xxx, half4(_1127).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1127).y) - half(1.0)))))) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1062 + _981)) - half(1.0)) + _981, half(0.0), half(1.0)));
    out.fragColor = float4(half4(_1199, half(1.0)));
    return out;
}

