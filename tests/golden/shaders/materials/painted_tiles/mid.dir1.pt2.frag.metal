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
    float3 _775 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _949 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _952 = facet_material_albedo.sample(facet_material_albedoSmplr, _949);
    float4 _962 = facet_material_relief.sample(facet_material_reliefSmplr, _949);
    half3 _966 = (half4(_962).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _972 = fract(_949 * 4.0);
    float _974 = _972.x;
    float _981 = _972.y;
    half3 _2074;
    do
    {
        half3 _1006 = half4(in.v_tangent).xyz;
        if (float(dot(_1006, _1006)) == 0.0)
        {
            _2074 = normalize(half3(in.v_normal));
            break;
        }
        _2074 = normalize(((_1006 * _966.x) + ((cross(half3(in.v_normal), _1006) * half(in.v_tangent.w)) * _966.y)) + (half3(in.v_normal) * _966.z));
        break;
    } while(false);
    half3 _1049 = clamp(half4(_952).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1058 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_974, 1.0 - _974), fast::min(_981, 1.0 - _981))))), half(0.0), half(1.0));
    half3 _1151 = reflect(-half3(_775), _2074);
    half4 _1206 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _1208 = _1206.x;
    half2 _1226 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_1208 * _1208, exp2(half(-9.27999973297119140625) * max(dot(_2074, half3(_775)), half(9.9999997473787516355514526367188e-05)))), _1208, _1206.y)) + _1206.zw;
    half3 _1234 = (half3(float3(0.039999999105930328369140625)) * _1226.x) + half3(_1226.y);
    float4 _1244 = facet_environment.sample(facet_environmentSmplr, float3(_1151), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _828 = half4(frame.lightDirection).xyz;
    half _1403 = clamp(dot(_1151, _828), half(0.0), half(1.0));
    half _1406 = _1403 * _1403;
    half4 _2148 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1406 * _1406, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1418 = _2148.x;
    float3 _1463 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1466 = dot(_1463, _1463);
    float3 _1471 = _1463 * rsqrt(fast::max(_1466, 9.9999999392252902907785028219223e-09));
    float _1475 = _1466 * float(frame.punctualLights[0].positionFalloff.w);
    float _1480 = fast::clamp(fma(-_1475, _1475, 1.0), 0.0, 1.0);
    float _1499 = fast::clamp(fma(dot(-_1471, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1655 = clamp(dot(_1151, half3(_1471)), half(0.0), half(1.0));
    half _1658 = _1655 * _1655;
    half4 _2173 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1658 * _1658, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1670 = _2173.x;
    float3 _1715 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1718 = dot(_1715, _1715);
    float3 _1723 = _1715 * rsqrt(fast::max(_1718, 9.9999999392252902907785028219223e-09));
    float _1727 = _1718 * float(frame.punctualLights[1].positionFalloff.w);
    float _1732 = fast::clamp(fma(-_1727, _1727, 1.0), 0.0, 1.0);
    float _1751 = fast::clamp(fma(dot(-_1723, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1907 = clamp(dot(_1151, half3(_1723)), half(0.0), half(1.0));
    half _1910 = _1907 * _1907;
    half4 _2199 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1910 * _1910, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1922 = _2199.x;
    half3 _1931 = (((fma(_1049 * half3(in.v_diffuseLight), max(half3(_1058), ((((((_1049 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1058) + ((_1049 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1058) + ((_1049 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1058), _1049 * half3(in.v_directDiffuse)) + ((half4(_1244).xyz * _1234) * _1058)) + min((_1234 * ((_1418 * _1418) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2074, _828), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1234 * ((_1670 * _1670) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1480) * half(_1480)) / fast::max(_1466, 9.9999997473787516355514526367188e-05)) * half(_1499)) * half(_1499)), float3(65504.0))) * clamp(dot(_2074, half3(_1471)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1234 * ((_1922 * _1922) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1732) * half(_1732)) / fast::max(_1718, 9.9999997473787516355514526367188e-05)) * half(_1751)) * half(_1751)), float3(65504.0))) * clamp(dot(_2074, half3(_1723)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1931, half(1.0)));
    return out;
}

