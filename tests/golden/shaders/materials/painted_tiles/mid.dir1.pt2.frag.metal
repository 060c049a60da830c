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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _677 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _825 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _828 = facet_material_albedo.sample(facet_material_albedoSmplr, _825);
    float4 _838 = facet_material_relief.sample(facet_material_reliefSmplr, _825);
    half3 _842 = (half4(_838).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1905;
    do
    {
        half3 _855 = half4(in.v_tangent).xyz;
        if (float(dot(_855, _855)) == 0.0)
        {
            _1905 = normalize(half3(in.v_normal));
            break;
        }
        _1905 = normalize(((_855 * _842.x) + ((cross(half3(in.v_normal), _855) * half(in.v_tangent.w)) * _842.y)) + (half3(in.v_normal) * _842.z));
        break;
    } while(false);
    half _933 = max(dot(_1905, half3(_677)), half(9.9999997473787516355514526367188e-05));
    float4 _996 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_933, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1015 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_996).y) - half(1.0)));
    float4 _1022 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_677), _1905)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _718 = half4(frame.lightDirection).xyz;
    half3 _1153 = normalize(half3(_677) + _718);
    half _1080 = clamp(dot(_1905, _718), half(0.0), half(1.0));
    half3 _1180 = cross(_1905, _1153);
    half _1183 = clamp(dot(_1905, _1153), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1200 = max(mix((half(2.0) * _1080) * _933, _1080 + _933, half(params.facet_alpha)), half(0.000244140625));
    half _1202 = half(1024.0) * half(params.facet_alpha);
    half _1207 = _1202 / (fma(_1183, _1183, dot(_1180, _1180)) * (half(6433.98193359375) * _1200));
    float3 _1255 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1258 = dot(_1255, _1255);
    float3 _1263 = _1255 * rsqrt(fast::max(_1258, 9.9999999392252902907785028219223e-09));
    float _1267 = _1258 * float(frame.punctualLights[0].positionFalloff.w);
    float _1272 = fast::clamp(fma(-_1267, _1267, 1.0), 0.0, 1.0);
    float _1291 = fast::clamp(fma(dot(-_1263, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1425 = normalize(half3(_677) + half3(_1263));
    half _1352 = clamp(dot(_1905, half3(_1263)), half(0.0), half(1.0));
    half3 _1452 = cross(_1905, _1425);
    half _1455 = clamp(dot(_1905, _1425), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1472 = max(mix((half(2.0) * _1352) * _933, _1352 + _933, half(params.facet_alpha)), half(0.000244140625));
    half _1479 = _1202 / (fma(_1455, _1455, dot(_1452, _1452)) * (half(6433.98193359375) * _1472));
    float3 _1527 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1530 = dot(_1527, _1527);
    float3 _1535 = _1527 * rsqrt(fast::max(_1530, 9.9999999392252902907785028219223e-09));
    float _1539 = _1530 * float(frame.punctualLights[1].positionFalloff.w);
    float _1544 = fast::clamp(fma(-_1539, _1539, 1.0), 0.0, 1.0);
    float _1563 = fast::clamp(fma(dot(-_1535, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1697 = normalize(half3(_677) + half3(_1535));
    half _1624 = clamp(dot(_1905, half3(_1535)), half(0.0), half(1.0));
    half3 _1724 = cross(_1905, _1697);
    half _1727 = clamp(dot(_1905, _1697), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1744 = max(mix((half(2.0) * _1624) * _933, _1624 + _933, half(params.facet_alpha)), half(0.000244140625));
    half _1751 = _1202 / (fma(_1727, _1727, dot(_1724, _1724)) * (half(6433.98193359375) * _1744));
    half3 _1763 = ((fma(clamp(half4(_828).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1022).xyz * (mix(half4(_996).xxx, half4(_996).yyy, half3(float3(0.039999999105930328369140625))) * _1015)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1207 * (_1207 * (half(6.283185482025146484375) * _1200)), half(65504.0))) * _1015) * (half4(frame.lightColor).xyz * _1080), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1479 * (_1479 * (half(6.283185482025146484375) * _1472)), half(65504.0))) * _1015) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1272) * half(_1272)) / fast::max(_1258, 9.9999997473787516355514526367188e-05)) * half(_1291)) * half(_1291)), float3(65504.0))) * _1352), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1751 * (_1751 * (half(6.283185482025146484375) * _1744)), half(65504.0))) * _1015) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1544) * half(_1544)) / fast::max(_1530, 9.9999997473787516355514526367188e-05)) * half(_1563)) * half(_1563)), float3(65504.0))) * _1624), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1763, half(1.0)));
    return out;
}

