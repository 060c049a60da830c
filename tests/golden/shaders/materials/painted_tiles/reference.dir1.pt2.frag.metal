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
    float3 _1010 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1166 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1169 = facet_material_albedo.sample(facet_material_albedoSmplr, _1166);
    float4 _1179 = facet_material_relief.sample(facet_material_reliefSmplr, _1166);
    float3 _1183 = (_1179.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1189 = fract(_1166 * 4.0);
    float _1191 = _1189.x;
    float _1198 = _1189.y;
    float3 _2718;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2718 = fast::normalize(in.v_normal);
            break;
        }
        _2718 = fast::normalize(((in.v_tangent.xyz * _1183.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1183.y)) + (in.v_normal * _1183.z));
        break;
    } while(false);
    float3 _1383 = fast::clamp(_1169.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1392 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1191, 1.0 - _1191), fast::min(_1198, 1.0 - _1198)))), 0.0, 1.0);
    float _1473 = fast::max(dot(_2718, _1010), 9.9999997473787516355514526367188e-05);
    float4 _1538 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1473, params.facet_perceptualRoughness), level(0.0));
    float3 _1557 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1538.y) - 1.0));
    float3 _1735 = fast::normalize(_1010 + frame.lightDirection.xyz);
    float _1656 = fast::clamp(dot(_2718, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1773 = cross(_2718, _1735);
    float _1776 = fast::clamp(dot(_2718, _1735), 0.0, 1.0) * params.facet_alpha;
    float _1785 = params.facet_alpha / fma(_1776, _1776, dot(_1773, _1773));
    float _1798 = params.facet_alpha * params.facet_alpha;
    float _1804 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1808 = sqrt(fma(_1473 * _1473, _1804, _1798));
    float _1831 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1735), 0.0, 1.0);
    float _1834 = _1831 * _1831;
    float3 _1687 = _1383 * 0.3183098733425140380859375;
    float3 _1864 = fma(_1383 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2718.y)) + (frame.sh[2].xyz * _2718.z)) + (frame.sh[3].xyz * _2718.x)) + (((((frame.sh[4].xyz * (_2718.x * _2718.y)) + (frame.sh[5].xyz * (_2718.y * _2718.z))) + (frame.sh[6].xyz * fma(3.0 * _2718.z, _2718.z, -1.0))) + (frame.sh[7].xyz * (_2718.x * _2718.z))) + (frame.sh[8].xyz * fma(_2718.x, _2718.x, -(_2718.y * _2718.y)))), float3(0.0)), fast::max(float3(_1392), ((((((_1383 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1392) + ((_1383 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1392) + ((_1383 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1392), (facet_environment.sample(facet_environmentSmplr, reflect(-_1010, _2718), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1538.xxx, _1538.yyy, float3(0.039999999105930328369140625)) * _1557)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1473 + _1392)) - 1.0) + _1392, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1834 * _1834) * _1831))) * (((_1785 * _1785) * 0.3183098733425140380859375) * (0.5 / fma(_1656, _1808, _1473 * sqrt(fma(_1656 * _1656, _1804, _1798))))), _1557, _1687) * (frame.lightColor.xyz * _1656), float3(65504.0));
    float3 _1899 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1902 = dot(_1899, _1899);
    float3 _1907 = _1899 * rsqrt(fast::max(_1902, 9.9999999392252902907785028219223e-09));
    float _1911 = _1902 * float(frame.punctualLights[0].positionFalloff.w);
    float _1916 = fast::clamp(fma(-_1911, _1911, 1.0), 0.0, 1.0);
    float _1935 = fast::clamp(fma(dot(-_1907, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2074 = fast::normalize(_1010 + _1907);
    float _1995 = fast::clamp(dot(_2718, _1907), 0.0, 1.0);
    float3 _2112 = cross(_2718, _2074);
    float _2115 = fast::clamp(dot(_2718, _2074), 0.0, 1.0) * params.facet_alpha;
    float _2124 = params.facet_alpha / fma(_2115, _2115, dot(_2112, _2112));
    float _2170 = 1.0 - fast::clamp(dot(_1907, _2074), 0.0, 1.0);
    float _2173 = _2170 * _2170;
    float3 _2238 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2241 = dot(_2238, _2238);
    float3 _2246 = _2238 * rsqrt(fast::max(_2241, 9.9999999392252902907785028219223e-09));
    float _2250 = _2241 * float(frame.punctualLights[1].positionFalloff.w);
    float _2255 = fast::clamp(fma(-_2250, _2250, 1.0), 0.0, 1.0);
    float _2274 = fast::clamp(fma(dot(-_2246, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2413 = fast::normalize(_1010 + _2246);
    float _2334 = fast::clamp(dot(_2718, _2246), 0.0, 1.0);
    float3 _2451 = cross(_2718, _2413);
    float _2454 = fast::clamp(dot(_2718, _2413), 0.0, 1.0) * params.facet_alpha;
    float _2463 = params.facet_alpha / fma(_2454, _2454, dot(_2451, _2451));
    float _2509 = 1.0 - fast::clamp(dot(_2246, _2413), 0.0, 1.0);
    float _2512 = _2509 * _2509;
    float3 _2542 = (_1864 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2173 * _2173) * _2170))) * (((_2124 * _2124) * 0.3183098733425140380859375) * (0.5 / fma(_1995, _1808, _1473 * sqrt(fma(_1995 * _1995, _1804, _1798))))), _1557, _1687) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1916 * _1916) / fast::max(_1902, 9.9999997473787516355514526367188e-05)) * _1935) * _1935)) * _1995), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2512 * _2512) * _2509))) * (((_2463 * _2463) * 0.3183098733425140380859375) * (0.5 / fma(_2334, _1808, _1473 * sqrt(fma(_2334 * _2334, _1804, _1798))))), _1557, _1687) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2255 * _2255) / fast::max(_2241, 9.9999997473787516355514526367188e-05)) * _2274) * _2274)) * _2334), float3(65504.0));
    out.fragColor = float4(_2542, 1.0);
    return out;
}

