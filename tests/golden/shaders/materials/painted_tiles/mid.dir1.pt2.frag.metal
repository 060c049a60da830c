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
    float3 _792 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _963 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _966 = facet_material_albedo.sample(facet_material_albedoSmplr, _963);
    float4 _976 = facet_material_relief.sample(facet_material_reliefSmplr, _963);
    half3 _980 = (half4(_976).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _986 = fract(_963 * 4.0);
    float _988 = _986.x;
    float _995 = _986.y;
    half3 _2162;
    do
    {
        half3 _1020 = half4(in.v_tangent).xyz;
        if (float(dot(_1020, _1020)) == 0.0)
        {
            _2162 = normalize(half3(in.v_normal));
            break;
        }
        _2162 = normalize(((_1020 * _980.x) + ((cross(half3(in.v_normal), _1020) * half(in.v_tangent.w)) * _980.y)) + (half3(in.v_normal) * _980.z));
        break;
    } while(false);
    half3 _1063 = clamp(half4(_966).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1072 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_988, 1.0 - _988), fast::min(_995, 1.0 - _995))))), half(0.0), half(1.0));
    half _1165 = max(dot(_2162, half3(_792)), half(9.9999997473787516355514526367188e-05));
    float4 _1230 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1165, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1249 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1230).y) - half(1.0)));
    float4 _1259 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_792), _2162)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _845 = half4(frame.lightDirection).xyz;
    half3 _1396 = normalize(half3(_792) + _845);
    half _1323 = clamp(dot(_2162, _845), half(0.0), half(1.0));
    half3 _1423 = cross(_2162, _1396);
    half _1426 = clamp(dot(_2162, _1396), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1443 = max(mix((half(2.0) * _1323) * _1165, _1323 + _1165, half(params.facet_alpha)), half(0.000244140625));
    half _1445 = half(1024.0) * half(params.facet_alpha);
    half _1450 = _1445 / (fma(_1426, _1426, dot(_1423, _1423)) * (half(6433.98193359375) * _1443));
    float3 _1498 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1501 = dot(_1498, _1498);
    float3 _1506 = _1498 * rsqrt(fast::max(_1501, 9.9999999392252902907785028219223e-09));
    float _1510 = _1501 * float(frame.punctualLights[0].positionFalloff.w);
    float _1515 = fast::clamp(fma(-_1510, _1510, 1.0), 0.0, 1.0);
    float _1534 = fast::clamp(fma(dot(-_1506, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1668 = normalize(half3(_792) + half3(_1506));
    half _1595 = clamp(dot(_2162, half3(_1506)), half(0.0), half(1.0));
    half3 _1695 = cross(_2162, _1668);
    half _1698 = clamp(dot(_2162, _1668), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1715 = max(mix((half(2.0) * _1595) * _1165, _1595 + _1165, half(params.facet_alpha)), half(0.000244140625));
    half _1722 = _1445 / (fma(_1698, _1698, dot(_1695, _1695)) * (half(6433.98193359375) * _1715));
    half3 _1734 = ((fma(_1063 * half3(in.v_diffuseLight), max(half3(_1072), ((((((_1063 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1072) + ((_1063 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1072) + ((_1063 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1072), _1063 * half3(in.v_directDiffuse)) + ((half4(_1259).xyz * (mix(half4(_1230).xxx, half4(_1230).yyy, half3(float3(0.039999999105930328369140625))) * _1249)) * _1072)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1450 * (_1450 * (half(6.283185482025146484375) * _1443)), half(65504.0))) * _1249) * (half4(frame.lightColor).xyz * _1323), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1722 * (_1722 * (half(6.283185482025146484375) * _1715)), half(65504.0))) * _1249) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1515) * half(_1515)) / fast::max(_1501, 9.9999997473787516355514526367188e-05)) * half(_1534)) * half(_1534)), float3(65504.0))) * _1595), half3(float3(65504.0)));
    float3 _1770 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1773 = dot(_1770, _1770);
    float3 _1778 = _1770 * rsqrt(fast::max(_1773, 9.9999999392252902907785028219223e-09));
    float _1782 = _1773 * float(frame.punctualLights[1].positionFalloff.w);
    float _1787 = fast::clamp(fma(-_1782, _1782, 1.0), 0.0, 1.0);
    float _1806 = fast::clamp(fma(dot(-_1778, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1940 = normalize(half3(_792) + half3(_1778));
    half _1867 = clamp(dot(_2162, half3(_1778)), half(0.0), half(1.0));
    half3 _1967 = cross(_2162, _1940);
    half _1970 = clamp(dot(_2162, _1940), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1987 = max(mix((half(2.0) * _1867) * _1165, _1867 + _1165, half(params.facet_alpha)), half(0.000244140625));
    half _1994 = _1445 / (fma(_1970, _1970, dot(_1967, _1967)) * (half(6433.98193359375) * _1987));
    out.fragColor = float4(half4(_1734 + min(((half3(float3(0.039999999105930328369140625)) * min(_1994 * (_1994 * (half(6.283185482025146484375) * _1987)), half(65504.0))) * _1249) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1787) * half(_1787)) / fast::max(_1773, 9.9999997473787516355514526367188e-05)) * half(_1806)) * half(_1806)), float3(65504.0))) * _1867), half3(float3(65504.0))), half(1.0)));
    return out;
}

