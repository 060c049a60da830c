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
    float3 _724 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _877 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _880 = facet_material_albedo.sample(facet_material_albedoSmplr, _877);
    float4 _890 = facet_material_relief.sample(facet_material_reliefSmplr, _877);
    half3 _894 = (half4(_890).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _900 = fract(_877 * 4.0);
    float _902 = _900.x;
    float _909 = _900.y;
    half3 _1775;
    do
    {
        half3 _934 = half4(in.v_tangent).xyz;
        if (float(dot(_934, _934)) == 0.0)
        {
            _1775 = normalize(half3(in.v_normal));
            break;
        }
        _1775 = normalize(((_934 * _894.x) + ((cross(half3(in.v_normal), _934) * half(in.v_tangent.w)) * _894.y)) + (half3(in.v_normal) * _894.z));
        break;
    } while(false);
    half3 _977 = clamp(half4(_880).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _983 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_902, 1.0 - _902), fast::min(_909, 1.0 - _909))))), half(0.0), half(1.0));
    half3 _1034 = reflect(-half3(_724), _1775);
    float4 _1096 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1775, half3(_724)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1122 = facet_environment.sample(facet_environmentSmplr, float3(_1034), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1049 = mix(half4(_1096).xxx, half4(_1096).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1096).y) - half(1.0))));
    float3 _1173 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1176 = dot(_1173, _1173);
    float3 _1181 = _1173 * rsqrt(fast::max(_1176, 9.9999999392252902907785028219223e-09));
    float _1185 = _1176 * float(frame.punctualLights[0].positionFalloff.w);
    float _1190 = fast::clamp(fma(-_1185, _1185, 1.0), 0.0, 1.0);
    float _1209 = fast::clamp(fma(dot(-_1181, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1365 = clamp(dot(_1034, half3(_1181)), half(0.0), half(1.0));
    half _1368 = _1365 * _1365;
    half4 _1855 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1368 * _1368, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1380 = _1855.x;
    float3 _1425 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1428 = dot(_1425, _1425);
    float3 _1433 = _1425 * rsqrt(fast::max(_1428, 9.9999999392252902907785028219223e-09));
    float _1437 = _1428 * float(frame.punctualLights[1].positionFalloff.w);
    float _1442 = fast::clamp(fma(-_1437, _1437, 1.0), 0.0, 1.0);
    float _1461 = fast::clamp(fma(dot(-_1433, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1617 = clamp(dot(_1034, half3(_1433)), half(0.0), half(1.0));
    half _1620 = _1617 * _1617;
    half4 _1881 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1620 * _1620, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1632 = _1881.x;
    half3 _1641 = ((fma(_977, half3(in.v_directDiffuse), (_977 * half3(in.v_diffuseLight)) * _983) + ((half4(_1122).xyz * _1049) * _983)) + min((_1049 * ((_1380 * _1380) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1190) * half(_1190)) / fast::max(_1176, 9.9999997473787516355514526367188e-05)) * half(_1209)) * half(_1209)), float3(65504.0))) * clamp(dot(_1775, half3(_1181)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1049 * ((_1632 * _1632) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1442) * half(_1442)) / fast::max(_1428, 9.9999997473787516355514526367188e-05)) * half(_1461)) * half(_1461)), float3(65504.0))) * clamp(dot(_1775, half3(_1433)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1641, half(1.0)));
    return out;
}

