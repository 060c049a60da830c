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
    float2 _928 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _931 = facet_material_albedo.sample(facet_material_albedoSmplr, _928);
    float4 _941 = facet_material_relief.sample(facet_material_reliefSmplr, _928);
    half3 _945 = (half4(_941).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _951 = fract(_928 * 4.0);
    float _953 = _951.x;
    float _960 = _951.y;
    half3 _1882;
    do
    {
        half3 _985 = half4(in.v_tangent).xyz;
        if (float(dot(_985, _985)) == 0.0)
        {
            _1882 = normalize(half3(in.v_normal));
            break;
        }
        _1882 = normalize(((_985 * _945.x) + ((cross(half3(in.v_normal), _985) * half(in.v_tangent.w)) * _945.y)) + (half3(in.v_normal) * _945.z));
        break;
    } while(false);
    half3 _1028 = clamp(half4(_931).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1037 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_953, 1.0 - _953), fast::min(_960, 1.0 - _960))))), half(0.0), half(1.0));
    half3 _1134 = reflect(-half3(_775), _1882);
    float4 _1196 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1882, half3(_775)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1225 = facet_environment.sample(facet_environmentSmplr, float3(_1134), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1149 = mix(half4(_1196).xxx, half4(_1196).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1196).y) - half(1.0))));
    float3 _1276 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1279 = dot(_1276, _1276);
    float3 _1284 = _1276 * rsqrt(fast::max(_1279, 9.9999999392252902907785028219223e-09));
    float _1288 = _1279 * float(frame.punctualLights[0].positionFalloff.w);
    float _1293 = fast::clamp(fma(-_1288, _1288, 1.0), 0.0, 1.0);
    float _1312 = fast::clamp(fma(dot(-_1284, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1468 = clamp(dot(_1134, half3(_1284)), half(0.0), half(1.0));
    half _1471 = _1468 * _1468;
    half4 _1973 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1471 * _1471, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1483 = _1973.x;
    float3 _1528 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1531 = dot(_1528, _1528);
    float3 _1536 = _1528 * rsqrt(fast::max(_1531, 9.9999999392252902907785028219223e-09));
    float _1540 = _1531 * float(frame.punctualLights[1].positionFalloff.w);
    float _1545 = fast::clamp(fma(-_1540, _1540, 1.0), 0.0, 1.0);
    float _1564 = fast::clamp(fma(dot(-_1536, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1720 = clamp(dot(_1134, half3(_1536)), half(0.0), half(1.0));
    half _1723 = _1720 * _1720;
    half4 _1999 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1723 * _1723, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1735 = _1999.x;
    half3 _1744 = ((fma(_1028 * half3(in.v_diffuseLight), max(half3(_1037), ((((((_1028 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1037) + ((_1028 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1037) + ((_1028 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1037), _1028 * half3(in.v_directDiffuse)) + ((half4(_1225).xyz * _1149) * _1037)) + min((_1149 * ((_1483 * _1483) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1293) * half(_1293)) / fast::max(_1279, 9.9999997473787516355514526367188e-05)) * half(_1312)) * half(_1312)), float3(65504.0))) * clamp(dot(_1882, half3(_1284)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1149 * ((_1735 * _1735) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1545) * half(_1545)) / fast::max(_1531, 9.9999997473787516355514526367188e-05)) * half(_1564)) * half(_1564)), float3(65504.0))) * clamp(dot(_1882, half3(_1536)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1744, half(1.0)));
    return out;
}

