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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
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
    half3 _2071;
    do
    {
        half3 _1006 = half4(in.v_tangent).xyz;
        if (float(dot(_1006, _1006)) == 0.0)
        {
            _2071 = normalize(half3(in.v_normal));
            break;
        }
        _2071 = normalize(((_1006 * _966.x) + ((cross(half3(in.v_normal), _1006) * half(in.v_tangent.w)) * _966.y)) + (half3(in.v_normal) * _966.z));
        break;
    } while(false);
    half3 _1049 = clamp(half4(_952).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1058 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_974, 1.0 - _974), fast::min(_981, 1.0 - _981))))), half(0.0), half(1.0));
    half3 _1155 = reflect(-half3(_775), _2071);
    float4 _1217 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_2071, half3(_775)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1246 = facet_environment.sample(facet_environmentSmplr, float3(_1155), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1170 = mix(half4(_1217).xxx, half4(_1217).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1217).y) - half(1.0))));
    half3 _828 = half4(frame.lightDirection).xyz;
    half _1405 = clamp(dot(_1155, _828), half(0.0), half(1.0));
    half _1408 = _1405 * _1405;
    half4 _2151 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1408 * _1408, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1420 = _2151.x;
    float3 _1465 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1468 = dot(_1465, _1465);
    float3 _1473 = _1465 * rsqrt(fast::max(_1468, 9.9999999392252902907785028219223e-09));
    float _1477 = _1468 * float(frame.punctualLights[0].positionFalloff.w);
    float _1482 = fast::clamp(fma(-_1477, _1477, 1.0), 0.0, 1.0);
    float _1501 = fast::clamp(fma(dot(-_1473, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1657 = clamp(dot(_1155, half3(_1473)), half(0.0), half(1.0));
    half _1660 = _1657 * _1657;
    half4 _2176 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1660 * _1660, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1672 = _2176.x;
    float3 _1717 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1720 = dot(_1717, _1717);
    float3 _1725 = _1717 * rsqrt(fast::max(_1720, 9.9999999392252902907785028219223e-09));
    float _1729 = _1720 * float(frame.punctualLights[1].positionFalloff.w);
    float _1734 = fast::clamp(fma(-_1729, _1729, 1.0), 0.0, 1.0);
    float _1753 = fast::clamp(fma(dot(-_1725, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1909 = clamp(dot(_1155, half3(_1725)), half(0.0), half(1.0));
    half _1912 = _1909 * _1909;
    half4 _2202 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1912 * _1912, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1924 = _2202.x;
    half3 _1933 = (((fma(_1049 * half3(in.v_diffuseLight), max(half3(_1058), ((((((_1049 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1058) + ((_1049 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1058) + ((_1049 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1058), _1049 * half3(in.v_directDiffuse)) + ((half4(_1246).xyz * _1170) * _1058)) + min((_1170 * ((_1420 * _1420) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2071, _828), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1170 * ((_1672 * _1672) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1482) * half(_1482)) / fast::max(_1468, 9.9999997473787516355514526367188e-05)) * half(_1501)) * half(_1501)), float3(65504.0))) * clamp(dot(_2071, half3(_1473)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1170 * ((_1924 * _1924) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1734) * half(_1734)) / fast::max(_1720, 9.9999997473787516355514526367188e-05)) * half(_1753)) * half(_1753)), float3(65504.0))) * clamp(dot(_2071, half3(_1725)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1933, half(1.0)));
    return out;
}

