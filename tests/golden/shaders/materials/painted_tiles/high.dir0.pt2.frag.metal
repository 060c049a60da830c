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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _1037 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1172 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1175 = facet_material_albedo.sample(facet_material_albedoSmplr, _1172);
    float4 _1185 = facet_material_relief.sample(facet_material_reliefSmplr, _1172);
    half3 _1189 = (half4(_1185).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1195 = fract(_1172 * 4.0);
    float _1197 = _1195.x;
    float _1204 = _1195.y;
    half3 _2493;
    do
    {
        half3 _1229 = half4(in.v_tangent).xyz;
        if (float(dot(_1229, _1229)) == 0.0)
        {
            _2493 = normalize(half3(in.v_normal));
            break;
        }
        _2493 = normalize(((_1229 * _1189.x) + ((cross(half3(in.v_normal), _1229) * half(in.v_tangent.w)) * _1189.y)) + (half3(in.v_normal) * _1189.z));
        break;
    } while(false);
    half3 _1366 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2493.y)) + (half4(frame.sh[2]).xyz * _2493.z)) + (half4(frame.sh[3]).xyz * _2493.x)) + (((((half4(frame.sh[4]).xyz * (_2493.x * _2493.y)) + (half4(frame.sh[5]).xyz * (_2493.y * _2493.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2493.z, _2493.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2493.x * _2493.z))) + (half4(frame.sh[8]).xyz * fma(_2493.x, _2493.x, half(-float(_2493.y * _2493.y))))), half3(float3(0.0)));
    half3 _1389 = clamp(half4(_1175).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1398 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1197, 1.0 - _1197), fast::min(_1204, 1.0 - _1204))))), half(0.0), half(1.0));
    half _1479 = max(dot(_2493, half3(_1037)), half(9.9999997473787516355514526367188e-05));
    float4 _1544 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1479, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1563 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1544).y) - half(1.0)));
    float4 _1570 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1037), _2493)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1647 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1650 = dot(_1647, _1647);
    float3 _1655 = _1647 * rsqrt(fast::max(_1650, 9.9999999392252902907785028219223e-09));
    float _1659 = _1650 * float(frame.punctualLights[0].positionFalloff.w);
    float _1664 = fast::clamp(fma(-_1659, _1659, 1.0), 0.0, 1.0);
    float _1683 = fast::clamp(fma(dot(-_1655, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1826 = fast::normalize(_1037 + _1655);
    half _1746 = clamp(dot(_2493, half3(_1655)), half(0.0), half(1.0));
    half _1866 = half(4096.0) * half(params.facet_alpha);
    half4 _1891 = half4(cross(_2493, half3(_1826)), half(params.facet_alpha) * clamp(dot(_2493, half3(_1826)), half(0.0), half(1.0))) * half(64.0);
    half _1872 = _1866 / dot(_1891, _1891);
    half _1902 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1908 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1912 = sqrt(fma(_1479 * _1479, _1908, _1902));
    half _1936 = half(1.0) - clamp(dot(half3(_1655), half3(_1826)), half(0.0), half(1.0));
    half _1939 = _1936 * _1936;
    half3 _1777 = _1389 * half(0.3183098733425140380859375);
    float3 _2005 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2008 = dot(_2005, _2005);
    float3 _2013 = _2005 * rsqrt(fast::max(_2008, 9.9999999392252902907785028219223e-09));
    float _2017 = _2008 * float(frame.punctualLights[1].positionFalloff.w);
    float _2022 = fast::clamp(fma(-_2017, _2017, 1.0), 0.0, 1.0);
    float _2041 = fast::clamp(fma(dot(-_2013, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2184 = fast::normalize(_1037 + _2013);
    half _2104 = clamp(dot(_2493, half3(_2013)), half(0.0), half(1.0));
    half4 _2249 = half4(cross(_2493, half3(_2184)), half(params.facet_alpha) * clamp(dot(_2493, half3(_2184)), half(0.0), half(1.0))) * half(64.0);
    half _2230 = _1866 / dot(_2249, _2249);
    half _2294 = half(1.0) - clamp(dot(half3(_2013), half3(_2184)), half(0.0), half(1.0));
    half _2297 = _2294 * _2294;
    half3 _2327 = (fma(_1389 * _1366, max(half3(_1398), ((((((_1389 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1398) + ((_1389 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1398) + ((_1389 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1398), (half4(_1570).xyz * (mix(half4(_1544).xxx, half4(_1544).yyy, half3(float3(0.039999999105930328369140625))) * _1563)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1479 + _1398)) - half(1.0)) + _1398, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1939 * _1939) * _1936))) * min(min((_1872 * _1872) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1746, _1912, _1479 * sqrt(fma(_1746 * _1746, _1908, _1902))), half(65504.0)), half(65504.0)), _1563, _1777) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1664) * half(_1664)) / fast::max(_1650, 9.9999997473787516355514526367188e-05)) * half(_1683)) * half(_1683)), float3(65504.0))) * _1746), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2297 * _2297) * _2294))) * min(min((_2230 * _2230) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2104, _1912, _1479 * sqrt(fma(_2104 * _2104, _1908, _1902))), half(65504.0)), half(65504.0)), _1563, _1777) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2022) * half(_2022)) / fast::max(_2008, 9.9999997473787516355514526367188e-05)) * half(_2041)) * half(_2041)), float3(65504.0))) * _2104), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2327, half(1.0)));
    return out;
}

