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
    float2 _913 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _916 = facet_material_albedo.sample(facet_material_albedoSmplr, _913);
    float4 _926 = facet_material_relief.sample(facet_material_reliefSmplr, _913);
    half3 _930 = (half4(_926).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _936 = fract(_913 * 4.0);
    float _938 = _936.x;
    float _945 = _936.y;
    half3 _1860;
    do
    {
        half3 _970 = half4(in.v_tangent).xyz;
        if (float(dot(_970, _970)) == 0.0)
        {
            _1860 = normalize(half3(in.v_normal));
            break;
        }
        _1860 = normalize(((_970 * _930.x) + ((cross(half3(in.v_normal), _970) * half(in.v_tangent.w)) * _930.y)) + (half3(in.v_normal) * _930.z));
        break;
    } while(false);
    half3 _1013 = clamp(half4(_916).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1022 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_938, 1.0 - _938), fast::min(_945, 1.0 - _945))))), half(0.0), half(1.0));
    half3 _1113 = reflect(-half3(_760), _1860);
    half4 _1171 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _1173 = _1171.x;
    half2 _1191 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_1173 * _1173, exp2(half(-9.27999973297119140625) * max(dot(_1860, half3(_760)), half(9.9999997473787516355514526367188e-05)))), _1173, _1171.y)) + _1171.zw;
    half3 _1199 = (half3(float3(0.039999999105930328369140625)) * _1191.x) + half3(_1191.y);
    float4 _1122 = facet_environment.sample(facet_environmentSmplr, float3(_1113), level(params.facet_environmentLod));
    float3 _1249 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1252 = dot(_1249, _1249);
    float3 _1257 = _1249 * rsqrt(fast::max(_1252, 9.9999999392252902907785028219223e-09));
    float _1261 = _1252 * float(frame.punctualLights[0].positionFalloff.w);
    float _1266 = fast::clamp(fma(-_1261, _1261, 1.0), 0.0, 1.0);
    float _1285 = fast::clamp(fma(dot(-_1257, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1441 = clamp(dot(_1113, half3(_1257)), half(0.0), half(1.0));
    half _1444 = _1441 * _1441;
    half4 _1941 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1444 * _1444, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1456 = _1941.x;
    float3 _1501 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1504 = dot(_1501, _1501);
    float3 _1509 = _1501 * rsqrt(fast::max(_1504, 9.9999999392252902907785028219223e-09));
    float _1513 = _1504 * float(frame.punctualLights[1].positionFalloff.w);
    float _1518 = fast::clamp(fma(-_1513, _1513, 1.0), 0.0, 1.0);
    float _1537 = fast::clamp(fma(dot(-_1509, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1693 = clamp(dot(_1113, half3(_1509)), half(0.0), half(1.0));
    half _1696 = _1693 * _1693;
    half4 _1967 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1696 * _1696, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1708 = _1967.x;
    half3 _1717 = ((fma(_1013 * half3(in.v_diffuseLight), max(half3(_1022), ((((((_1013 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1022) + ((_1013 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1022) + ((_1013 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1022), _1013 * half3(in.v_directDiffuse)) + ((half4(_1122).xyz * _1199) * _1022)) + min((_1199 * ((_1456 * _1456) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1266) * half(_1266)) / fast::max(_1252, 9.9999997473787516355514526367188e-05)) * half(_1285)) * half(_1285)), float3(65504.0))) * clamp(dot(_1860, half3(_1257)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1199 * ((_1708 * _1708) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1518) * half(_1518)) / fast::max(_1504, 9.9999997473787516355514526367188e-05)) * half(_1537)) * half(_1537)), float3(65504.0))) * clamp(dot(_1860, half3(_1509)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1717, half(1.0)));
    return out;
}

