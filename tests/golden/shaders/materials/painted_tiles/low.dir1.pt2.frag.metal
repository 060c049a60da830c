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
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _951 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _954 = facet_material_albedo.sample(facet_material_albedoSmplr, _951);
    float4 _964 = facet_material_relief.sample(facet_material_reliefSmplr, _951);
    half3 _968 = (half4(_964).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _974 = fract(_951 * 4.0);
    float _976 = _974.x;
    float _983 = _974.y;
    half3 _2075;
    do
    {
        half3 _1008 = half4(in.v_tangent).xyz;
        if (float(dot(_1008, _1008)) == 0.0)
        {
            _2075 = normalize(half3(in.v_normal));
            break;
        }
        _2075 = normalize(((_1008 * _968.x) + ((cross(half3(in.v_normal), _1008) * half(in.v_tangent.w)) * _968.y)) + (half3(in.v_normal) * _968.z));
        break;
    } while(false);
    half3 _1051 = clamp(half4(_954).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1060 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_976, 1.0 - _976), fast::min(_983, 1.0 - _983))))), half(0.0), half(1.0));
    half3 _1157 = reflect(-half3(_777), _2075);
    float4 _1219 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_2075, half3(_777)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1250 = facet_environment.sample(facet_environmentSmplr, float3(_1157), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1172 = mix(half4(_1219).xxx, half4(_1219).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1219).y) - half(1.0))));
    half3 _830 = half4(frame.lightDirection).xyz;
    half _1409 = clamp(dot(_1157, _830), half(0.0), half(1.0));
    half _1412 = _1409 * _1409;
    half4 _2155 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1412 * _1412, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1424 = _2155.x;
    float3 _1469 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1472 = dot(_1469, _1469);
    float3 _1477 = _1469 * rsqrt(fast::max(_1472, 9.9999999392252902907785028219223e-09));
    float _1481 = _1472 * float(frame.punctualLights[0].positionFalloff.w);
    float _1486 = fast::clamp(fma(-_1481, _1481, 1.0), 0.0, 1.0);
    float _1505 = fast::clamp(fma(dot(-_1477, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1661 = clamp(dot(_1157, half3(_1477)), half(0.0), half(1.0));
    half _1664 = _1661 * _1661;
    half4 _2180 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1664 * _1664, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1676 = _2180.x;
    float3 _1721 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1724 = dot(_1721, _1721);
    float3 _1729 = _1721 * rsqrt(fast::max(_1724, 9.9999999392252902907785028219223e-09));
    float _1733 = _1724 * float(frame.punctualLights[1].positionFalloff.w);
    float _1738 = fast::clamp(fma(-_1733, _1733, 1.0), 0.0, 1.0);
    float _1757 = fast::clamp(fma(dot(-_1729, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1913 = clamp(dot(_1157, half3(_1729)), half(0.0), half(1.0));
    half _1916 = _1913 * _1913;
    half4 _2206 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1916 * _1916, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1928 = _2206.x;
    half3 _1937 = (((fma(_1051 * half3(in.v_diffuseLight), max(half3(_1060), ((((((_1051 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1060) + ((_1051 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1060) + ((_1051 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1060), _1051 * half3(in.v_directDiffuse)) + ((half4(_1250).xyz * _1172) * _1060)) + min((_1172 * ((_1424 * _1424) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2075, _830), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1172 * ((_1676 * _1676) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1486) * half(_1486)) / fast::max(_1472, 9.9999997473787516355514526367188e-05)) * half(_1505)) * half(_1505)), float3(65504.0))) * clamp(dot(_2075, half3(_1477)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1172 * ((_1928 * _1928) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1738) * half(_1738)) / fast::max(_1724, 9.9999997473787516355514526367188e-05)) * half(_1757)) * half(_1757)), float3(65504.0))) * clamp(dot(_2075, half3(_1729)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1937, half(1.0)));
    return out;
}

