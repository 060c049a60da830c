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
    float3 _752 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _926 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _929 = facet_material_albedo.sample(facet_material_albedoSmplr, _926);
    float4 _939 = facet_material_relief.sample(facet_material_reliefSmplr, _926);
    half3 _943 = (half4(_939).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _949 = fract(_926 * 4.0);
    float _951 = _949.x;
    float _958 = _949.y;
    half3 _2029;
    do
    {
        half3 _983 = half4(in.v_tangent).xyz;
        if (float(dot(_983, _983)) == 0.0)
        {
            _2029 = normalize(half3(in.v_normal));
            break;
        }
        _2029 = normalize(((_983 * _943.x) + ((cross(half3(in.v_normal), _983) * half(in.v_tangent.w)) * _943.y)) + (half3(in.v_normal) * _943.z));
        break;
    } while(false);
    half3 _1026 = clamp(half4(_929).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1035 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_951, 1.0 - _951), fast::min(_958, 1.0 - _958))))), half(0.0), half(1.0));
    half3 _1130 = reflect(-half3(_752), _2029);
    float4 _1186 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_2029, half3(_752)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1195 = mix(half4(_1186).xxx, half4(_1186).yyy, half3(float3(0.039999999105930328369140625)));
    float4 _1205 = facet_environment.sample(facet_environmentSmplr, float3(_1130), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _805 = half4(frame.lightDirection).xyz;
    half _1364 = clamp(dot(_1130, _805), half(0.0), half(1.0));
    half _1367 = _1364 * _1364;
    half4 _2104 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1367 * _1367, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1379 = _2104.x;
    float3 _1424 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1427 = dot(_1424, _1424);
    float3 _1432 = _1424 * rsqrt(fast::max(_1427, 9.9999999392252902907785028219223e-09));
    float _1436 = _1427 * float(frame.punctualLights[0].positionFalloff.w);
    float _1441 = fast::clamp(fma(-_1436, _1436, 1.0), 0.0, 1.0);
    float _1460 = fast::clamp(fma(dot(-_1432, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1616 = clamp(dot(_1130, half3(_1432)), half(0.0), half(1.0));
    half _1619 = _1616 * _1616;
    half4 _2129 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1619 * _1619, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1631 = _2129.x;
    float3 _1676 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1679 = dot(_1676, _1676);
    float3 _1684 = _1676 * rsqrt(fast::max(_1679, 9.9999999392252902907785028219223e-09));
    float _1688 = _1679 * float(frame.punctualLights[1].positionFalloff.w);
    float _1693 = fast::clamp(fma(-_1688, _1688, 1.0), 0.0, 1.0);
    float _1712 = fast::clamp(fma(dot(-_1684, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1868 = clamp(dot(_1130, half3(_1684)), half(0.0), half(1.0));
    half _1871 = _1868 * _1868;
    half4 _2155 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1871 * _1871, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1883 = _2155.x;
    half3 _1892 = (((fma(_1026 * half3(in.v_diffuseLight), max(half3(_1035), ((((((_1026 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1035) + ((_1026 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1035) + ((_1026 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1035), _1026 * half3(in.v_directDiffuse)) + ((half4(_1205).xyz * _1195) * _1035)) + min((_1195 * ((_1379 * _1379) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2029, _805), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1195 * ((_1631 * _1631) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1441) * half(_1441)) / fast::max(_1427, 9.9999997473787516355514526367188e-05)) * half(_1460)) * half(_1460)), float3(65504.0))) * clamp(dot(_2029, half3(_1432)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1195 * ((_1883 * _1883) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1693) * half(_1693)) / fast::max(_1679, 9.9999997473787516355514526367188e-05)) * half(_1712)) * half(_1712)), float3(65504.0))) * clamp(dot(_2029, half3(_1684)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1892, half(1.0)));
    return out;
}

