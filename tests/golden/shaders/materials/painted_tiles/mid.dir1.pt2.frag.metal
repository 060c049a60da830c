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
    float3 _807 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _978 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _981 = facet_material_albedo.sample(facet_material_albedoSmplr, _978);
    float4 _991 = facet_material_relief.sample(facet_material_reliefSmplr, _978);
    half3 _995 = (half4(_991).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1001 = fract(_978 * 4.0);
    float _1003 = _1001.x;
    float _1010 = _1001.y;
    half3 _2207;
    do
    {
        half3 _1035 = half4(in.v_tangent).xyz;
        if (float(dot(_1035, _1035)) == 0.0)
        {
            _2207 = normalize(half3(in.v_normal));
            break;
        }
        _2207 = normalize(((_1035 * _995.x) + ((cross(half3(in.v_normal), _1035) * half(in.v_tangent.w)) * _995.y)) + (half3(in.v_normal) * _995.z));
        break;
    } while(false);
    half3 _1078 = clamp(half4(_981).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1087 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1003, 1.0 - _1003), fast::min(_1010, 1.0 - _1010))))), half(0.0), half(1.0));
    half _1180 = max(dot(_2207, half3(_807)), half(9.9999997473787516355514526367188e-05));
    float4 _1245 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1180, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1264 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1245).y) - half(1.0)));
    float4 _1271 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_807), _2207)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _860 = half4(frame.lightDirection).xyz;
    half3 _1408 = normalize(half3(_807) + _860);
    half _1335 = clamp(dot(_2207, _860), half(0.0), half(1.0));
    half4 _1477 = half4(cross(_2207, _1408), half(params.facet_alpha) * clamp(dot(_2207, _1408), half(0.0), half(1.0))) * half(64.0);
    half _1451 = half(4096.0) * half(params.facet_alpha);
    half _1454 = half(6.283185482025146484375) * max(mix((half(2.0) * _1335) * _1180, _1335 + _1180, half(params.facet_alpha)), half(0.000244140625));
    half _1456 = _1451 / (dot(_1477, _1477) * _1454);
    float3 _1521 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1524 = dot(_1521, _1521);
    float3 _1529 = _1521 * rsqrt(fast::max(_1524, 9.9999999392252902907785028219223e-09));
    float _1533 = _1524 * float(frame.punctualLights[0].positionFalloff.w);
    float _1538 = fast::clamp(fma(-_1533, _1533, 1.0), 0.0, 1.0);
    float _1557 = fast::clamp(fma(dot(-_1529, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1691 = normalize(half3(_807) + half3(_1529));
    half _1618 = clamp(dot(_2207, half3(_1529)), half(0.0), half(1.0));
    half4 _1760 = half4(cross(_2207, _1691), half(params.facet_alpha) * clamp(dot(_2207, _1691), half(0.0), half(1.0))) * half(64.0);
    half _1737 = half(6.283185482025146484375) * max(mix((half(2.0) * _1618) * _1180, _1618 + _1180, half(params.facet_alpha)), half(0.000244140625));
    half _1739 = _1451 / (dot(_1760, _1760) * _1737);
    half3 _1768 = ((fma(_1078 * half3(in.v_diffuseLight), max(half3(_1087), ((((((_1078 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1087) + ((_1078 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1087) + ((_1078 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1087), _1078 * half3(in.v_directDiffuse)) + ((half4(_1271).xyz * (mix(half4(_1245).xxx, half4(_1245).yyy, half3(float3(0.039999999105930328369140625))) * _1264)) * _1087)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1456 * (_1456 * _1454), half(65504.0))) * _1264) * (half4(frame.lightColor).xyz * _1335), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1739 * (_1739 * _1737), half(65504.0))) * _1264) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1538) * half(_1538)) / fast::max(_1524, 9.9999997473787516355514526367188e-05)) * half(_1557)) * half(_1557)), float3(65504.0))) * _1618), half3(float3(65504.0)));
    float3 _1804 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1807 = dot(_1804, _1804);
    float3 _1812 = _1804 * rsqrt(fast::max(_1807, 9.9999999392252902907785028219223e-09));
    float _1816 = _1807 * float(frame.punctualLights[1].positionFalloff.w);
    float _1821 = fast::clamp(fma(-_1816, _1816, 1.0), 0.0, 1.0);
    float _1840 = fast::clamp(fma(dot(-_1812, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1974 = normalize(half3(_807) + half3(_1812));
    half _1901 = clamp(dot(_2207, half3(_1812)), half(0.0), half(1.0));
    half4 _2043 = half4(cross(_2207, _1974), half(params.facet_alpha) * clamp(dot(_2207, _1974), half(0.0), half(1.0))) * half(64.0);
    half _2020 = half(6.283185482025146484375) * max(mix((half(2.0) * _1901) * _1180, _1901 + _1180, half(params.facet_alpha)), half(0.000244140625));
    half _2022 = _1451 / (dot(_2043, _2043) * _2020);
    half3 _2051 = _1768 + min(((half3(float3(0.039999999105930328369140625)) * min(_2022 * (_2022 * _2020), half(65504.0))) * _1264) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1821) * half(_1821)) / fast::max(_1807, 9.9999997473787516355514526367188e-05)) * half(_1840)) * half(_1840)), float3(65504.0))) * _1901), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2051, half(1.0)));
    return out;
}

