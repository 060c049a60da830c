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
    float3 _794 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _965 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _968 = facet_material_albedo.sample(facet_material_albedoSmplr, _965);
    float4 _978 = facet_material_relief.sample(facet_material_reliefSmplr, _965);
    half3 _982 = (half4(_978).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _988 = fract(_965 * 4.0);
    float _990 = _988.x;
    float _997 = _988.y;
    half3 _2166;
    do
    {
        half3 _1022 = half4(in.v_tangent).xyz;
        if (float(dot(_1022, _1022)) == 0.0)
        {
            _2166 = normalize(half3(in.v_normal));
            break;
        }
        _2166 = normalize(((_1022 * _982.x) + ((cross(half3(in.v_normal), _1022) * half(in.v_tangent.w)) * _982.y)) + (half3(in.v_normal) * _982.z));
        break;
    } while(false);
    half3 _1065 = clamp(half4(_968).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1074 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_990, 1.0 - _990), fast::min(_997, 1.0 - _997))))), half(0.0), half(1.0));
    half _1167 = max(dot(_2166, half3(_794)), half(9.9999997473787516355514526367188e-05));
    float4 _1232 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1167, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1251 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1232).y) - half(1.0)));
    float4 _1263 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_794), _2166)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _847 = half4(frame.lightDirection).xyz;
    half3 _1400 = normalize(half3(_794) + _847);
    half _1327 = clamp(dot(_2166, _847), half(0.0), half(1.0));
    half3 _1427 = cross(_2166, _1400);
    half _1430 = clamp(dot(_2166, _1400), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1447 = max(mix((half(2.0) * _1327) * _1167, _1327 + _1167, half(params.facet_alpha)), half(0.000244140625));
    half _1449 = half(1024.0) * half(params.facet_alpha);
    half _1454 = _1449 / (fma(_1430, _1430, dot(_1427, _1427)) * (half(6433.98193359375) * _1447));
    float3 _1502 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1505 = dot(_1502, _1502);
    float3 _1510 = _1502 * rsqrt(fast::max(_1505, 9.9999999392252902907785028219223e-09));
    float _1514 = _1505 * float(frame.punctualLights[0].positionFalloff.w);
    float _1519 = fast::clamp(fma(-_1514, _1514, 1.0), 0.0, 1.0);
    float _1538 = fast::clamp(fma(dot(-_1510, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1672 = normalize(half3(_794) + half3(_1510));
    half _1599 = clamp(dot(_2166, half3(_1510)), half(0.0), half(1.0));
    half3 _1699 = cross(_2166, _1672);
    half _1702 = clamp(dot(_2166, _1672), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1719 = max(mix((half(2.0) * _1599) * _1167, _1599 + _1167, half(params.facet_alpha)), half(0.000244140625));
    half _1726 = _1449 / (fma(_1702, _1702, dot(_1699, _1699)) * (half(6433.98193359375) * _1719));
    half3 _1738 = ((fma(_1065 * half3(in.v_diffuseLight), max(half3(_1074), ((((((_1065 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1074) + ((_1065 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1074) + ((_1065 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1074), _1065 * half3(in.v_directDiffuse)) + ((half4(_1263).xyz * (mix(half4(_1232).xxx, half4(_1232).yyy, half3(float3(0.039999999105930328369140625))) * _1251)) * _1074)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1454 * (_1454 * (half(6.283185482025146484375) * _1447)), half(65504.0))) * _1251) * (half4(frame.lightColor).xyz * _1327), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1726 * (_1726 * (half(6.283185482025146484375) * _1719)), half(65504.0))) * _1251) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1519) * half(_1519)) / fast::max(_1505, 9.9999997473787516355514526367188e-05)) * half(_1538)) * half(_1538)), float3(65504.0))) * _1599), half3(float3(65504.0)));
    float3 _1774 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1777 = dot(_1774, _1774);
    float3 _1782 = _1774 * rsqrt(fast::max(_1777, 9.9999999392252902907785028219223e-09));
    float _1786 = _1777 * float(frame.punctualLights[1].positionFalloff.w);
    float _1791 = fast::clamp(fma(-_1786, _1786, 1.0), 0.0, 1.0);
    float _1810 = fast::clamp(fma(dot(-_1782, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1944 = normalize(half3(_794) + half3(_1782));
    half _1871 = clamp(dot(_2166, half3(_1782)), half(0.0), half(1.0));
    half3 _1971 = cross(_2166, _1944);
    half _1974 = clamp(dot(_2166, _1944), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1991 = max(mix((half(2.0) * _1871) * _1167, _1871 + _1167, half(params.facet_alpha)), half(0.000244140625));
    half _1998 = _1449 / (fma(_1974, _1974, dot(_1971, _1971)) * (half(6433.98193359375) * _1991));
    out.fragColor = float4(half4(_1738 + min(((half3(float3(0.039999999105930328369140625)) * min(_1998 * (_1998 * (half(6.283185482025146484375) * _1991)), half(65504.0))) * _1251) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1791) * half(_1791)) / fast::max(_1777, 9.9999997473787516355514526367188e-05)) * half(_1810)) * half(_1810)), float3(65504.0))) * _1871), half3(float3(65504.0))), half(1.0)));
    return out;
}

