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
    float3 _741 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _879 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _882 = facet_material_albedo.sample(facet_material_albedoSmplr, _879);
    float4 _892 = facet_material_relief.sample(facet_material_reliefSmplr, _879);
    half3 _896 = (half4(_892).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _902 = fract(_879 * 4.0);
    float _904 = _902.x;
    float _911 = _902.y;
    half3 _1812;
    do
    {
        half3 _936 = half4(in.v_tangent).xyz;
        if (float(dot(_936, _936)) == 0.0)
        {
            _1812 = normalize(half3(in.v_normal));
            break;
        }
        _1812 = normalize(((_936 * _896.x) + ((cross(half3(in.v_normal), _936) * half(in.v_tangent.w)) * _896.y)) + (half3(in.v_normal) * _896.z));
        break;
    } while(false);
    half _985 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_904, 1.0 - _904), fast::min(_911, 1.0 - _911))))), half(0.0), half(1.0));
    half _1020 = max(dot(_1812, half3(_741)), half(9.9999997473787516355514526367188e-05));
    float4 _1085 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1020, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1104 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1085).y) - half(1.0)));
    float4 _1111 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_741), _1812)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1162 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1165 = dot(_1162, _1162);
    float3 _1170 = _1162 * rsqrt(fast::max(_1165, 9.9999999392252902907785028219223e-09));
    float _1174 = _1165 * float(frame.punctualLights[0].positionFalloff.w);
    float _1179 = fast::clamp(fma(-_1174, _1174, 1.0), 0.0, 1.0);
    float _1198 = fast::clamp(fma(dot(-_1170, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1332 = normalize(half3(_741) + half3(_1170));
    half _1259 = clamp(dot(_1812, half3(_1170)), half(0.0), half(1.0));
    half3 _1359 = cross(_1812, _1332);
    half _1362 = clamp(dot(_1812, _1332), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1379 = max(mix((half(2.0) * _1259) * _1020, _1259 + _1020, half(params.facet_alpha)), half(0.000244140625));
    half _1381 = half(1024.0) * half(params.facet_alpha);
    half _1386 = _1381 / (fma(_1362, _1362, dot(_1359, _1359)) * (half(6433.98193359375) * _1379));
    float3 _1434 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1437 = dot(_1434, _1434);
    float3 _1442 = _1434 * rsqrt(fast::max(_1437, 9.9999999392252902907785028219223e-09));
    float _1446 = _1437 * float(frame.punctualLights[1].positionFalloff.w);
    float _1451 = fast::clamp(fma(-_1446, _1446, 1.0), 0.0, 1.0);
    float _1470 = fast::clamp(fma(dot(-_1442, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1604 = normalize(half3(_741) + half3(_1442));
    half _1531 = clamp(dot(_1812, half3(_1442)), half(0.0), half(1.0));
    half3 _1631 = cross(_1812, _1604);
    half _1634 = clamp(dot(_1812, _1604), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1651 = max(mix((half(2.0) * _1531) * _1020, _1531 + _1020, half(params.facet_alpha)), half(0.000244140625));
    half _1658 = _1381 / (fma(_1634, _1634, dot(_1631, _1631)) * (half(6433.98193359375) * _1651));
    half3 _1670 = (((((clamp(half4(_882).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0)) * half3(in.v_diffuseLight)) * _985) + ((half4(_1111).xyz * (mix(half4(_1085).xxx, half4(_1085).yyy, half3(float3(0.039999999105930328369140625))) * _1104)) * _985)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1386 * (_1386 * (half(6.283185482025146484375) * _1379)), half(65504.0))) * _1104) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1179) * half(_1179)) / fast::max(_1165, 9.9999997473787516355514526367188e-05)) * half(_1198)) * half(_1198)), float3(65504.0))) * _1259), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1658 * (_1658 * (half(6.283185482025146484375) * _1651)), half(65504.0))) * _1104) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1451) * half(_1451)) / fast::max(_1437, 9.9999997473787516355514526367188e-05)) * half(_1470)) * half(_1470)), float3(65504.0))) * _1531), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1670, half(1.0)));
    return out;
}

