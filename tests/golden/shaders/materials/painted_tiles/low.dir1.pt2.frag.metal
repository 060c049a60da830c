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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _737 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _911 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _914 = facet_material_albedo.sample(facet_material_albedoSmplr, _911);
    float4 _924 = facet_material_relief.sample(facet_material_reliefSmplr, _911);
    half3 _928 = (half4(_924).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _934 = fract(_911 * 4.0);
    float _936 = _934.x;
    float _943 = _934.y;
    half3 _2004;
    do
    {
        half3 _968 = half4(in.v_tangent).xyz;
        if (float(dot(_968, _968)) == 0.0)
        {
            _2004 = normalize(half3(in.v_normal));
            break;
        }
        _2004 = normalize(((_968 * _928.x) + ((cross(half3(in.v_normal), _968) * half(in.v_tangent.w)) * _928.y)) + (half3(in.v_normal) * _928.z));
        break;
    } while(false);
    half3 _1011 = clamp(half4(_914).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1020 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_936, 1.0 - _936), fast::min(_943, 1.0 - _943))))), half(0.0), half(1.0));
    half3 _1113 = reflect(-half3(_737), _2004);
    float4 _1172 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_2004, half3(_737)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1181 = mix(half4(_1172).xxx, half4(_1172).yyy, half3(float3(0.039999999105930328369140625)));
    float4 _1124 = facet_environment.sample(facet_environmentSmplr, float3(_1113), level(params.facet_environmentLod));
    half3 _790 = half4(frame.lightDirection).xyz;
    half _1339 = clamp(dot(_1113, _790), half(0.0), half(1.0));
    half _1342 = _1339 * _1339;
    half4 _2075 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1342 * _1342, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1354 = _2075.x;
    float3 _1399 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1402 = dot(_1399, _1399);
    float3 _1407 = _1399 * rsqrt(fast::max(_1402, 9.9999999392252902907785028219223e-09));
    float _1411 = _1402 * float(frame.punctualLights[0].positionFalloff.w);
    float _1416 = fast::clamp(fma(-_1411, _1411, 1.0), 0.0, 1.0);
    float _1435 = fast::clamp(fma(dot(-_1407, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1591 = clamp(dot(_1113, half3(_1407)), half(0.0), half(1.0));
    half _1594 = _1591 * _1591;
    half4 _2100 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1594 * _1594, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1606 = _2100.x;
    float3 _1651 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1654 = dot(_1651, _1651);
    float3 _1659 = _1651 * rsqrt(fast::max(_1654, 9.9999999392252902907785028219223e-09));
    float _1663 = _1654 * float(frame.punctualLights[1].positionFalloff.w);
    float _1668 = fast::clamp(fma(-_1663, _1663, 1.0), 0.0, 1.0);
    float _1687 = fast::clamp(fma(dot(-_1659, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1843 = clamp(dot(_1113, half3(_1659)), half(0.0), half(1.0));
    half _1846 = _1843 * _1843;
    half4 _2126 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1846 * _1846, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1858 = _2126.x;
    half3 _1867 = (((fma(_1011 * half3(in.v_diffuseLight), max(half3(_1020), ((((((_1011 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1020) + ((_1011 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1020) + ((_1011 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1020), _1011 * half3(in.v_directDiffuse)) + ((half4(_1124).xyz * _1181) * _1020)) + min((_1181 * ((_1354 * _1354) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_2004, _790), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1181 * ((_1606 * _1606) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1416) * half(_1416)) / fast::max(_1402, 9.9999997473787516355514526367188e-05)) * half(_1435)) * half(_1435)), float3(65504.0))) * clamp(dot(_2004, half3(_1407)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1181 * ((_1858 * _1858) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1668) * half(_1668)) / fast::max(_1654, 9.9999997473787516355514526367188e-05)) * half(_1687)) * half(_1687)), float3(65504.0))) * clamp(dot(_2004, half3(_1659)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1867, half(1.0)));
    return out;
}

