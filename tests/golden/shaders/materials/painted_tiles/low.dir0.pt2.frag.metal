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
    float3 _772 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _925 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _928 = facet_material_albedo.sample(facet_material_albedoSmplr, _925);
    float4 _938 = facet_material_relief.sample(facet_material_reliefSmplr, _925);
    half3 _942 = (half4(_938).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _948 = fract(_925 * 4.0);
    float _950 = _948.x;
    float _957 = _948.y;
    half3 _1876;
    do
    {
        half3 _982 = half4(in.v_tangent).xyz;
        if (float(dot(_982, _982)) == 0.0)
        {
            _1876 = normalize(half3(in.v_normal));
            break;
        }
        _1876 = normalize(((_982 * _942.x) + ((cross(half3(in.v_normal), _982) * half(in.v_tangent.w)) * _942.y)) + (half3(in.v_normal) * _942.z));
        break;
    } while(false);
    half3 _1025 = clamp(half4(_928).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1034 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_950, 1.0 - _950), fast::min(_957, 1.0 - _957))))), half(0.0), half(1.0));
    half3 _1131 = reflect(-half3(_772), _1876);
    float4 _1193 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1876, half3(_772)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1219 = facet_environment.sample(facet_environmentSmplr, float3(_1131), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1146 = mix(half4(_1193).xxx, half4(_1193).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1193).y) - half(1.0))));
    float3 _1270 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1273 = dot(_1270, _1270);
    float3 _1278 = _1270 * rsqrt(fast::max(_1273, 9.9999999392252902907785028219223e-09));
    float _1282 = _1273 * float(frame.punctualLights[0].positionFalloff.w);
    float _1287 = fast::clamp(fma(-_1282, _1282, 1.0), 0.0, 1.0);
    float _1306 = fast::clamp(fma(dot(-_1278, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1462 = clamp(dot(_1131, half3(_1278)), half(0.0), half(1.0));
    half _1465 = _1462 * _1462;
    half4 _1965 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1465 * _1465, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1477 = _1965.x;
    float3 _1522 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1525 = dot(_1522, _1522);
    float3 _1530 = _1522 * rsqrt(fast::max(_1525, 9.9999999392252902907785028219223e-09));
    float _1534 = _1525 * float(frame.punctualLights[1].positionFalloff.w);
    float _1539 = fast::clamp(fma(-_1534, _1534, 1.0), 0.0, 1.0);
    float _1558 = fast::clamp(fma(dot(-_1530, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1714 = clamp(dot(_1131, half3(_1530)), half(0.0), half(1.0));
    half _1717 = _1714 * _1714;
    half4 _1991 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1717 * _1717, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1729 = _1991.x;
    half3 _1738 = ((fma(_1025 * half3(in.v_diffuseLight), max(half3(_1034), ((((((_1025 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1034) + ((_1025 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1034) + ((_1025 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1034), _1025 * half3(in.v_directDiffuse)) + ((half4(_1219).xyz * _1146) * _1034)) + min((_1146 * ((_1477 * _1477) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1287) * half(_1287)) / fast::max(_1273, 9.9999997473787516355514526367188e-05)) * half(_1306)) * half(_1306)), float3(65504.0))) * clamp(dot(_1876, half3(_1278)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1146 * ((_1729 * _1729) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1539) * half(_1539)) / fast::max(_1525, 9.9999997473787516355514526367188e-05)) * half(_1558)) * half(_1558)), float3(65504.0))) * clamp(dot(_1876, half3(_1530)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1738, half(1.0)));
    return out;
}

