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
    float2 _828 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _831 = facet_material_albedo.sample(facet_material_albedoSmplr, _828);
    float4 _841 = facet_material_relief.sample(facet_material_reliefSmplr, _828);
    half3 _845 = (half4(_841).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1908;
    do
    {
        half3 _858 = half4(in.v_tangent).xyz;
        if (float(dot(_858, _858)) == 0.0)
        {
            _1908 = normalize(half3(in.v_normal));
            break;
        }
        _1908 = normalize(((_858 * _845.x) + ((cross(half3(in.v_normal), _858) * half(in.v_tangent.w)) * _845.y)) + (half3(in.v_normal) * _845.z));
        break;
    } while(false);
    half _936 = max(dot(_1908, half3(_677)), half(9.9999997473787516355514526367188e-05));
    float4 _999 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_936, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1018 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_999).y) - half(1.0)));
    float4 _1025 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_677), _1908)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _718 = half4(frame.lightDirection).xyz;
    half3 _1156 = normalize(half3(_677) + _718);
    half _1083 = clamp(dot(_1908, _718), half(0.0), half(1.0));
    half3 _1183 = cross(_1908, _1156);
    half _1186 = clamp(dot(_1908, _1156), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1203 = max(mix((half(2.0) * _1083) * _936, _1083 + _936, half(params.facet_alpha)), half(0.000244140625));
    half _1205 = half(1024.0) * half(params.facet_alpha);
    half _1210 = _1205 / (fma(_1186, _1186, dot(_1183, _1183)) * (half(6433.98193359375) * _1203));
    float3 _1258 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1261 = dot(_1258, _1258);
    float3 _1266 = _1258 * rsqrt(fast::max(_1261, 9.9999999392252902907785028219223e-09));
    float _1270 = _1261 * float(frame.punctualLights[0].positionFalloff.w);
    float _1275 = fast::clamp(fma(-_1270, _1270, 1.0), 0.0, 1.0);
    float _1294 = fast::clamp(fma(dot(-_1266, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1428 = normalize(half3(_677) + half3(_1266));
    half _1355 = clamp(dot(_1908, half3(_1266)), half(0.0), half(1.0));
    half3 _1455 = cross(_1908, _1428);
    half _1458 = clamp(dot(_1908, _1428), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1475 = max(mix((half(2.0) * _1355) * _936, _1355 + _936, half(params.facet_alpha)), half(0.000244140625));
    half _1482 = _1205 / (fma(_1458, _1458, dot(_1455, _1455)) * (half(6433.98193359375) * _1475));
    float3 _1530 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1533 = dot(_1530, _1530);
    float3 _1538 = _1530 * rsqrt(fast::max(_1533, 9.9999999392252902907785028219223e-09));
    float _1542 = _1533 * float(frame.punctualLights[1].positionFalloff.w);
    float _1547 = fast::clamp(fma(-_1542, _1542, 1.0), 0.0, 1.0);
    float _1566 = fast::clamp(fma(dot(-_1538, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1700 = normalize(half3(_677) + half3(_1538));
    half _1627 = clamp(dot(_1908, half3(_1538)), half(0.0), half(1.0));
    half3 _1727 = cross(_1908, _1700);
    half _1730 = clamp(dot(_1908, _1700), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1747 = max(mix((half(2.0) * _1627) * _936, _1627 + _936, half(params.facet_alpha)), half(0.000244140625));
    half _1754 = _1205 / (fma(_1730, _1730, dot(_1727, _1727)) * (half(6433.98193359375) * _1747));
    half3 _1766 = ((fma(clamp(half4(_831).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1025).xyz * (mix(half4(_999).xxx, half4(_999).yyy, half3(float3(0.039999999105930328369140625))) * _1018)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1210 * (_1210 * (half(6.283185482025146484375) * _1203)), half(65504.0))) * _1018) * (half4(frame.lightColor).xyz * _1083), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1482 * (_1482 * (half(6.283185482025146484375) * _1475)), half(65504.0))) * _1018) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1275) * half(_1275)) / fast::max(_1261, 9.9999997473787516355514526367188e-05)) * half(_1294)) * half(_1294)), float3(65504.0))) * _1355), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1754 * (_1754 * (half(6.283185482025146484375) * _1747)), half(65504.0))) * _1018) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1547) * half(_1547)) / fast::max(_1533, 9.9999997473787516355514526367188e-05)) * half(_1566)) * half(_1566)), float3(65504.0))) * _1627), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1766, half(1.0)));
    return out;
}

