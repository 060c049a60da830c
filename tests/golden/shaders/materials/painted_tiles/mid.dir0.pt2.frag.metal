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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _741 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _891 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _894 = facet_material_albedo.sample(facet_material_albedoSmplr, _891);
    float4 _904 = facet_material_relief.sample(facet_material_reliefSmplr, _891);
    half3 _908 = (half4(_904).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _914 = fract(_891 * 4.0);
    float _916 = _914.x;
    float _923 = _914.y;
    half3 _1840;
    do
    {
        half3 _948 = half4(in.v_tangent).xyz;
        if (float(dot(_948, _948)) == 0.0)
        {
            _1840 = normalize(half3(in.v_normal));
            break;
        }
        _1840 = normalize(((_948 * _908.x) + ((cross(half3(in.v_normal), _948) * half(in.v_tangent.w)) * _908.y)) + (half3(in.v_normal) * _908.z));
        break;
    } while(false);
    half3 _991 = clamp(half4(_894).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _997 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_916, 1.0 - _916), fast::min(_923, 1.0 - _923))))), half(0.0), half(1.0));
    half _1044 = max(dot(_1840, half3(_741)), half(9.9999997473787516355514526367188e-05));
    float4 _1109 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1044, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1128 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1109).y) - half(1.0)));
    float4 _1135 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_741), _1840)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1186 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1189 = dot(_1186, _1186);
    float3 _1194 = _1186 * rsqrt(fast::max(_1189, 9.9999999392252902907785028219223e-09));
    float _1198 = _1189 * float(frame.punctualLights[0].positionFalloff.w);
    float _1203 = fast::clamp(fma(-_1198, _1198, 1.0), 0.0, 1.0);
    float _1222 = fast::clamp(fma(dot(-_1194, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1356 = normalize(half3(_741) + half3(_1194));
    half _1283 = clamp(dot(_1840, half3(_1194)), half(0.0), half(1.0));
    half3 _1383 = cross(_1840, _1356);
    half _1386 = clamp(dot(_1840, _1356), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1403 = max(mix((half(2.0) * _1283) * _1044, _1283 + _1044, half(params.facet_alpha)), half(0.000244140625));
    half _1405 = half(1024.0) * half(params.facet_alpha);
    half _1410 = _1405 / (fma(_1386, _1386, dot(_1383, _1383)) * (half(6433.98193359375) * _1403));
    float3 _1458 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1461 = dot(_1458, _1458);
    float3 _1466 = _1458 * rsqrt(fast::max(_1461, 9.9999999392252902907785028219223e-09));
    float _1470 = _1461 * float(frame.punctualLights[1].positionFalloff.w);
    float _1475 = fast::clamp(fma(-_1470, _1470, 1.0), 0.0, 1.0);
    float _1494 = fast::clamp(fma(dot(-_1466, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1628 = normalize(half3(_741) + half3(_1466));
    half _1555 = clamp(dot(_1840, half3(_1466)), half(0.0), half(1.0));
    half3 _1655 = cross(_1840, _1628);
    half _1658 = clamp(dot(_1840, _1628), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1675 = max(mix((half(2.0) * _1555) * _1044, _1555 + _1044, half(params.facet_alpha)), half(0.000244140625));
    half _1682 = _1405 / (fma(_1658, _1658, dot(_1655, _1655)) * (half(6433.98193359375) * _1675));
    half3 _1694 = ((fma(_991, half3(in.v_directDiffuse), (_991 * half3(in.v_diffuseLight)) * _997) + ((half4(_1135).xyz * (mix(half4(_1109).xxx, half4(_1109).yyy, half3(float3(0.039999999105930328369140625))) * _1128)) * _997)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1410 * (_1410 * (half(6.283185482025146484375) * _1403)), half(65504.0))) * _1128) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1203) * half(_1203)) / fast::max(_1189, 9.9999997473787516355514526367188e-05)) * half(_1222)) * half(_1222)), float3(65504.0))) * _1283), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1682 * (_1682 * (half(6.283185482025146484375) * _1675)), half(65504.0))) * _1128) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1475) * half(_1475)) / fast::max(_1461, 9.9999997473787516355514526367188e-05)) * half(_1494)) * half(_1494)), float3(65504.0))) * _1555), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1694, half(1.0)));
    return out;
}

