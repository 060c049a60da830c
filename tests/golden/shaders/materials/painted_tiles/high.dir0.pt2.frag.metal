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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _861 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _996 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _999 = facet_material_albedo.sample(facet_material_albedoSmplr, _996);
    float4 _1009 = facet_material_relief.sample(facet_material_reliefSmplr, _996);
    half3 _1013 = (half4(_1009).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1019 = fract(_996 * 4.0);
    float _1021 = _1019.x;
    float _1028 = _1019.y;
    half3 _2114;
    do
    {
        half3 _1053 = half4(in.v_tangent).xyz;
        if (float(dot(_1053, _1053)) == 0.0)
        {
            _2114 = normalize(half3(in.v_normal));
            break;
        }
        _2114 = normalize(((_1053 * _1013.x) + ((cross(half3(in.v_normal), _1053) * half(in.v_tangent.w)) * _1013.y)) + (half3(in.v_normal) * _1013.z));
        break;
    } while(false);
    float4 _1089 = facet_irradiance.sample(facet_irradianceSmplr, float3(_2114), level(0.0));
    half3 _1113 = clamp(half4(_999).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1122 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1021, 1.0 - _1021), fast::min(_1028, 1.0 - _1028))))), half(0.0), half(1.0));
    half _1201 = max(dot(_2114, half3(_861)), half(9.9999997473787516355514526367188e-05));
    float4 _1260 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1201, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1279 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_861), _2114)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1330 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1333 = dot(_1330, _1330);
    float3 _1338 = _1330 * rsqrt(fast::max(_1333, 9.9999999392252902907785028219223e-09));
    float _1342 = _1333 * float(frame.punctualLights[0].positionFalloff.w);
    float _1347 = fast::clamp(fma(-_1342, _1342, 1.0), 0.0, 1.0);
    float _1366 = fast::clamp(fma(dot(-_1338, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1506 = fast::normalize(_861 + _1338);
    half _1429 = clamp(dot(_2114, half3(_1338)), half(0.0), half(1.0));
    half _1546 = half(4096.0) * half(params.facet_alpha);
    half4 _1571 = half4(cross(_2114, half3(_1506)), half(params.facet_alpha) * clamp(dot(_2114, half3(_1506)), half(0.0), half(1.0))) * half(64.0);
    half _1552 = _1546 / dot(_1571, _1571);
    half _1596 = half(1.0) - clamp(dot(half3(_1338), half3(_1506)), half(0.0), half(1.0));
    half _1599 = _1596 * _1596;
    half3 _1457 = _1113 * half(0.3183098733425140380859375);
    float3 _1665 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1668 = dot(_1665, _1665);
    float3 _1673 = _1665 * rsqrt(fast::max(_1668, 9.9999999392252902907785028219223e-09));
    float _1677 = _1668 * float(frame.punctualLights[1].positionFalloff.w);
    float _1682 = fast::clamp(fma(-_1677, _1677, 1.0), 0.0, 1.0);
    float _1701 = fast::clamp(fma(dot(-_1673, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1841 = fast::normalize(_861 + _1673);
    half _1764 = clamp(dot(_2114, half3(_1673)), half(0.0), half(1.0));
    half4 _1906 = half4(cross(_2114, half3(_1841)), half(params.facet_alpha) * clamp(dot(_2114, half3(_1841)), half(0.0), half(1.0))) * half(64.0);
    half _1887 = _1546 / dot(_1906, _1906);
    half _1931 = half(1.0) - clamp(dot(half3(_1673), half3(_1841)), half(0.0), half(1.0));
    half _1934 = _1931 * _1931;
    half3 _1964 = (fma(_1113 * half4(_1089).xyz, max(half3(_1122), ((((((_1113 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1122) + ((_1113 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1122) + ((_1113 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1122), (half4(_1279).xyz * mix(half4(_1260).xxx, half4(_1260).yyy, half3(float3(0.039999999105930328369140625)))) * _1122) + min((_1457 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1599 * _1599) * _1596))) * min(min((_1552 * _1552) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1429) * _1201, _1429 + _1201, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1347) * half(_1347)) / fast::max(_1333, 9.9999997473787516355514526367188e-05)) * half(_1366)) * half(_1366)), float3(65504.0))) * _1429), half3(float3(65504.0)))) + min((_1457 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1934 * _1934) * _1931))) * min(min((_1887 * _1887) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1764) * _1201, _1764 + _1201, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1682) * half(_1682)) / fast::max(_1668, 9.9999997473787516355514526367188e-05)) * half(_1701)) * half(_1701)), float3(65504.0))) * _1764), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1964, half(1.0)));
    return out;
}

