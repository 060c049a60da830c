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
    float3 _1028 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1184 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1187 = facet_material_albedo.sample(facet_material_albedoSmplr, _1184);
    float4 _1197 = facet_material_relief.sample(facet_material_reliefSmplr, _1184);
    float3 _1201 = (_1197.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1207 = fract(_1184 * 4.0);
    float _1209 = _1207.x;
    float _1216 = _1207.y;
    float3 _2766;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2766 = fast::normalize(in.v_normal);
            break;
        }
        _2766 = fast::normalize(((in.v_tangent.xyz * _1201.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1201.y)) + (in.v_normal * _1201.z));
        break;
    } while(false);
    float3 _1401 = fast::clamp(_1187.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1410 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1209, 1.0 - _1209), fast::min(_1216, 1.0 - _1216)))), 0.0, 1.0);
    float _1491 = fast::max(dot(_2766, _1028), 9.9999997473787516355514526367188e-05);
    float4 _1556 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1491, params.facet_perceptualRoughness), level(0.0));
    float3 _1575 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1556.y) - 1.0));
    float3 _1753 = fast::normalize(_1028 + frame.lightDirection.xyz);
    float _1674 = fast::clamp(dot(_2766, frame.lightDirection.xyz), 0.0, 1.0);
    float _1791 = 4096.0 * params.facet_alpha;
    float4 _1815 = float4(cross(_2766, _1753), params.facet_alpha * fast::clamp(dot(_2766, _1753), 0.0, 1.0)) * 64.0;
    float _1797 = _1791 / dot(_1815, _1815);
    float _1826 = params.facet_alpha * params.facet_alpha;
    float _1832 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1836 = sqrt(fma(_1491 * _1491, _1832, _1826));
    float _1859 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1753), 0.0, 1.0);
    float _1862 = _1859 * _1859;
    float3 _1705 = _1401 * 0.3183098733425140380859375;
    float3 _1892 = fma(_1401 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2766.y)) + (frame.sh[2].xyz * _2766.z)) + (frame.sh[3].xyz * _2766.x)) + (((((frame.sh[4].xyz * (_2766.x * _2766.y)) + (frame.sh[5].xyz * (_2766.y * _2766.z))) + (frame.sh[6].xyz * fma(3.0 * _2766.z, _2766.z, -1.0))) + (frame.sh[7].xyz * (_2766.x * _2766.z))) + (frame.sh[8].xyz * fma(_2766.x, _2766.x, -(_2766.y * _2766.y)))), float3(0.0)), fast::max(float3(_1410), ((((((_1401 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1410) + ((_1401 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1410) + ((_1401 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1410), (facet_environment.sample(facet_environmentSmplr, reflect(-_1028, _2766), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1556.xxx, _1556.yyy, float3(0.039999999105930328369140625)) * _1575)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1491 + _1410)) - 1.0) + _1410, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1862 * _1862) * _1859))) * (((_1797 * _1797) * 0.3183098733425140380859375) * (0.5 / fma(_1674, _1836, _1491 * sqrt(fma(_1674 * _1674, _1832, _1826))))), _1575, _1705) * (frame.lightColor.xyz * _1674), float3(65504.0));
    float3 _1927 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1930 = dot(_1927, _1927);
    float3 _1935 = _1927 * rsqrt(fast::max(_1930, 9.9999999392252902907785028219223e-09));
    float _1939 = _1930 * float(frame.punctualLights[0].positionFalloff.w);
    float _1944 = fast::clamp(fma(-_1939, _1939, 1.0), 0.0, 1.0);
    float _1963 = fast::clamp(fma(dot(-_1935, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2102 = fast::normalize(_1028 + _1935);
    float _2023 = fast::clamp(dot(_2766, _1935), 0.0, 1.0);
    float4 _2164 = float4(cross(_2766, _2102), params.facet_alpha * fast::clamp(dot(_2766, _2102), 0.0, 1.0)) * 64.0;
    float _2146 = _1791 / dot(_2164, _2164);
    float _2208 = 1.0 - fast::clamp(dot(_1935, _2102), 0.0, 1.0);
    float _2211 = _2208 * _2208;
    float3 _2276 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2279 = dot(_2276, _2276);
    float3 _2284 = _2276 * rsqrt(fast::max(_2279, 9.9999999392252902907785028219223e-09));
    float _2288 = _2279 * float(frame.punctualLights[1].positionFalloff.w);
    float _2293 = fast::clamp(fma(-_2288, _2288, 1.0), 0.0, 1.0);
    float _2312 = fast::clamp(fma(dot(-_2284, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2451 = fast::normalize(_1028 + _2284);
    float _2372 = fast::clamp(dot(_2766, _2284), 0.0, 1.0);
    float4 _2513 = float4(cross(_2766, _2451), params.facet_alpha * fast::clamp(dot(_2766, _2451), 0.0, 1.0)) * 64.0;
    float _2495 = _1791 / dot(_2513, _2513);
    float _2557 = 1.0 - fast::clamp(dot(_2284, _2451), 0.0, 1.0);
    float _2560 = _2557 * _2557;
    float3 _2590 = (_1892 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2211 * _2211) * _2208))) * (((_2146 * _2146) * 0.3183098733425140380859375) * (0.5 / fma(_2023, _1836, _1491 * sqrt(fma(_2023 * _2023, _1832, _1826))))), _1575, _1705) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1944 * _1944) / fast::max(_1930, 9.9999997473787516355514526367188e-05)) * _1963) * _1963)) * _2023), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2560 * _2560) * _2557))) * (((_2495 * _2495) * 0.3183098733425140380859375) * (0.5 / fma(_2372, _1836, _1491 * sqrt(fma(_2372 * _2372, _1832, _1826))))), _1575, _1705) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2293 * _2293) / fast::max(_2279, 9.9999997473787516355514526367188e-05)) * _2312) * _2312)) * _2372), float3(65504.0));
    out.fragColor = float4(_2590, 1.0);
    return out;
}

