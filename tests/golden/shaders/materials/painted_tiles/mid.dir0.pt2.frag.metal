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
    float3 _809 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _959 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _962 = facet_material_albedo.sample(facet_material_albedoSmplr, _959);
    float4 _972 = facet_material_relief.sample(facet_material_reliefSmplr, _959);
    half3 _976 = (half4(_972).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _982 = fract(_959 * 4.0);
    float _984 = _982.x;
    float _991 = _982.y;
    half3 _1987;
    do
    {
        half3 _1016 = half4(in.v_tangent).xyz;
        if (float(dot(_1016, _1016)) == 0.0)
        {
            _1987 = normalize(half3(in.v_normal));
            break;
        }
        _1987 = normalize(((_1016 * _976.x) + ((cross(half3(in.v_normal), _1016) * half(in.v_tangent.w)) * _976.y)) + (half3(in.v_normal) * _976.z));
        break;
    } while(false);
    half3 _1059 = clamp(half4(_962).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1068 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_984, 1.0 - _984), fast::min(_991, 1.0 - _991))))), half(0.0), half(1.0));
    half _1161 = max(dot(_1987, half3(_809)), half(9.9999997473787516355514526367188e-05));
    float4 _1226 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1161, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1245 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1226).y) - half(1.0)));
    float4 _1252 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_809), _1987)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1303 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1306 = dot(_1303, _1303);
    float3 _1311 = _1303 * rsqrt(fast::max(_1306, 9.9999999392252902907785028219223e-09));
    float _1315 = _1306 * float(frame.punctualLights[0].positionFalloff.w);
    float _1320 = fast::clamp(fma(-_1315, _1315, 1.0), 0.0, 1.0);
    float _1339 = fast::clamp(fma(dot(-_1311, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1473 = normalize(half3(_809) + half3(_1311));
    half _1400 = clamp(dot(_1987, half3(_1311)), half(0.0), half(1.0));
    half3 _1536 = cross(_1987, _1473) * half(64.0);
    half _1539 = half(64.0) * half(params.facet_alpha);
    half _1540 = clamp(dot(_1987, _1473), half(0.0), half(1.0)) * _1539;
    half _1516 = half(4096.0) * half(params.facet_alpha);
    half _1519 = half(6.283185482025146484375) * max(mix((half(2.0) * _1400) * _1161, _1400 + _1161, half(params.facet_alpha)), half(0.000244140625));
    half _1521 = _1516 / (fma(_1540, _1540, dot(_1536, _1536)) * _1519);
    float3 _1588 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1591 = dot(_1588, _1588);
    float3 _1596 = _1588 * rsqrt(fast::max(_1591, 9.9999999392252902907785028219223e-09));
    float _1600 = _1591 * float(frame.punctualLights[1].positionFalloff.w);
    float _1605 = fast::clamp(fma(-_1600, _1600, 1.0), 0.0, 1.0);
    float _1624 = fast::clamp(fma(dot(-_1596, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1758 = normalize(half3(_809) + half3(_1596));
    half _1685 = clamp(dot(_1987, half3(_1596)), half(0.0), half(1.0));
    half3 _1821 = cross(_1987, _1758) * half(64.0);
    half _1825 = clamp(dot(_1987, _1758), half(0.0), half(1.0)) * _1539;
    half _1804 = half(6.283185482025146484375) * max(mix((half(2.0) * _1685) * _1161, _1685 + _1161, half(params.facet_alpha)), half(0.000244140625));
    half _1806 = _1516 / (fma(_1825, _1825, dot(_1821, _1821)) * _1804);
    half3 _1837 = ((fma(_1059 * half3(in.v_diffuseLight), max(half3(_1068), ((((((_1059 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1068) + ((_1059 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1068) + ((_1059 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1068), _1059 * half3(in.v_directDiffuse)) + ((half4(_1252).xyz * (mix(half4(_1226).xxx, half4(_1226).yyy, half3(float3(0.039999999105930328369140625))) * _1245)) * _1068)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1521 * (_1521 * _1519), half(65504.0))) * _1245) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1320) * half(_1320)) / fast::max(_1306, 9.9999997473787516355514526367188e-05)) * half(_1339)) * half(_1339)), float3(65504.0))) * _1400), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1806 * (_1806 * _1804), half(65504.0))) * _1245) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1605) * half(_1605)) / fast::max(_1591, 9.9999997473787516355514526367188e-05)) * half(_1624)) * half(_1624)), float3(65504.0))) * _1685), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1837, half(1.0)));
    return out;
}

