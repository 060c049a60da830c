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
    float2 _930 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _933 = facet_material_albedo.sample(facet_material_albedoSmplr, _930);
    float4 _943 = facet_material_relief.sample(facet_material_reliefSmplr, _930);
    half3 _947 = (half4(_943).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _953 = fract(_930 * 4.0);
    float _955 = _953.x;
    float _962 = _953.y;
    half3 _1886;
    do
    {
        half3 _987 = half4(in.v_tangent).xyz;
        if (float(dot(_987, _987)) == 0.0)
        {
            _1886 = normalize(half3(in.v_normal));
            break;
        }
        _1886 = normalize(((_987 * _947.x) + ((cross(half3(in.v_normal), _987) * half(in.v_tangent.w)) * _947.y)) + (half3(in.v_normal) * _947.z));
        break;
    } while(false);
    half3 _1030 = clamp(half4(_933).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1039 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_955, 1.0 - _955), fast::min(_962, 1.0 - _962))))), half(0.0), half(1.0));
    half3 _1136 = reflect(-half3(_777), _1886);
    float4 _1198 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1886, half3(_777)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1229 = facet_environment.sample(facet_environmentSmplr, float3(_1136), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1151 = mix(half4(_1198).xxx, half4(_1198).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1198).y) - half(1.0))));
    float3 _1280 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1283 = dot(_1280, _1280);
    float3 _1288 = _1280 * rsqrt(fast::max(_1283, 9.9999999392252902907785028219223e-09));
    float _1292 = _1283 * float(frame.punctualLights[0].positionFalloff.w);
    float _1297 = fast::clamp(fma(-_1292, _1292, 1.0), 0.0, 1.0);
    float _1316 = fast::clamp(fma(dot(-_1288, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1472 = clamp(dot(_1136, half3(_1288)), half(0.0), half(1.0));
    half _1475 = _1472 * _1472;
    half4 _1977 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1475 * _1475, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1487 = _1977.x;
    float3 _1532 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1535 = dot(_1532, _1532);
    float3 _1540 = _1532 * rsqrt(fast::max(_1535, 9.9999999392252902907785028219223e-09));
    float _1544 = _1535 * float(frame.punctualLights[1].positionFalloff.w);
    float _1549 = fast::clamp(fma(-_1544, _1544, 1.0), 0.0, 1.0);
    float _1568 = fast::clamp(fma(dot(-_1540, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1724 = clamp(dot(_1136, half3(_1540)), half(0.0), half(1.0));
    half _1727 = _1724 * _1724;
    half4 _2003 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1727 * _1727, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1739 = _2003.x;
    half3 _1748 = ((fma(_1030 * half3(in.v_diffuseLight), max(half3(_1039), ((((((_1030 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1039) + ((_1030 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1039) + ((_1030 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1039), _1030 * half3(in.v_directDiffuse)) + ((half4(_1229).xyz * _1151) * _1039)) + min((_1151 * ((_1487 * _1487) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1297) * half(_1297)) / fast::max(_1283, 9.9999997473787516355514526367188e-05)) * half(_1316)) * half(_1316)), float3(65504.0))) * clamp(dot(_1886, half3(_1288)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1151 * ((_1739 * _1739) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1549) * half(_1549)) / fast::max(_1535, 9.9999997473787516355514526367188e-05)) * half(_1568)) * half(_1568)), float3(65504.0))) * clamp(dot(_1886, half3(_1540)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1748, half(1.0)));
    return out;
}

