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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
    float3 v_diffuseLight [[user(locn4)]];
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _760 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _934 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _937 = facet_material_albedo.sample(facet_material_albedoSmplr, _934);
    float4 _947 = facet_material_relief.sample(facet_material_reliefSmplr, _934);
    half3 _951 = (half4(_947).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _957 = fract(_934 * 4.0);
    float _959 = _957.x;
    float _966 = _957.y;
    half3 _2049;
    do
    {
        half3 _991 = half4(in.v_tangent).xyz;
        if (float(dot(_991, _991)) == 0.0)
        {
            _2049 = normalize(half3(in.v_normal));
            break;
        }
        _2049 = normalize(((_991 * _951.x) + ((cross(half3(in.v_normal), _991) * half(in.v_tangent.w)) * _951.y)) + (half3(in.v_normal) * _951.z));
        break;
    } while(false);
    half3 _1034 = clamp(half4(_937).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1043 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_959, 1.0 - _959), fast::min(_966, 1.0 - _966))))), half(0.0), half(1.0));
    half3 _1134 = reflect(-half3(_760), _2049);
    half4 _1192 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _1194 = _1192.x;
    half2 _1212 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_1194 * _1194, exp2(half(-9.27999973297119140625) * max(dot(_2049, half3(_760)), half(9.9999997473787516355514526367188e-05)))), _1194, _1192.y)) + _1192.zw;
    half3 _1220 = (half3(float3(0.039999999105930328369140625)) * _1212.x) + half3(_1212.y);
    float4 _1143 = facet_environment.sample(facet_environmentSmplr, float3(_1134), level(params.facet_environmentLod));
    half3 _813 = half4(frame.lightDirection).xyz;
    half _1378 = clamp(dot(_1134, _813), half(0.0), half(1.0));
    half _1381 = _1378 * _1378;
    half4 _2119 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1381 * _1381, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1393 = _2119.x;
    float3 _1438 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1441 = dot(_1438, _1438);
    float3 _1446 = _1438 * rsqrt(fast::max(_1441, 9.9999999392252902907785028219223e-09));
    float _1450 = _1441 * float(frame.punctualLights[0].positionFalloff.w);
    float _1455 = fast::clamp(fma(-_1450, _1450, 1.0), 0.0, 1.0);
    float _1474 = fast::clamp(fma(dot(-_1446, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1630 = clamp(dot(_1134, half3(_1446)), half(0.0), half(1.0));
    half _1633 = _1630 * _1630;
    half4 _2144 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1633 * _1633, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1645 = _2144.x;
    float3 _1690 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1693 = dot(_1690, _1690);
    float3 _1698 = _1690 * rsqrt(fast::max(_1693, 9.9999999392252902907785028219223e-09));
    float _1702 = _1693 * float(frame.punctualLights[1].positionFalloff.w);
    float _1707 = fast::clamp(fma(-_1702, _1702, 1.0), 0.0, 1.0);
    float _1726 = fast::clamp(fma(dot(-_1698, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1882 = clamp(dot(_1134, half3(_1698)), half(0.0), half(1.0));
    half _1885 = _1882 * _1882;
    half4 _2170 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1885 * _1885, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1897 = _2170.x;
    half3 _1906 = (((fma(_1034 * half3(in.v_diffuseLight), max(half3(_1043), ((((((_1034 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1043) + ((_1034 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1043) + ((_1034 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1043), _1034 * half3(in.v_directDiffuse)) + ((half4(_1143).xyz * _1220) * _1043)) + min((_1220 * ((_1393 * _1393) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2049, _813), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1220 * ((_1645 * _1645) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1455) * half(_1455)) / fast::max(_1441, 9.9999997473787516355514526367188e-05)) * half(_1474)) * half(_1474)), float3(65504.0))) * clamp(dot(_2049, half3(_1446)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1220 * ((_1897 * _1897) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1707) * half(_1707)) / fast::max(_1693, 9.9999997473787516355514526367188e-05)) * half(_1726)) * half(_1726)), float3(65504.0))) * clamp(dot(_2049, half3(_1698)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1906, half(1.0)));
    return out;
}

