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
    float3 _1013 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1169 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1172 = facet_material_albedo.sample(facet_material_albedoSmplr, _1169);
    float4 _1182 = facet_material_relief.sample(facet_material_reliefSmplr, _1169);
    float3 _1186 = (_1182.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1192 = fract(_1169 * 4.0);
    float _1194 = _1192.x;
    float _1201 = _1192.y;
    float3 _2724;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2724 = fast::normalize(in.v_normal);
            break;
        }
        _2724 = fast::normalize(((in.v_tangent.xyz * _1186.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1186.y)) + (in.v_normal * _1186.z));
        break;
    } while(false);
    float3 _1386 = fast::clamp(_1172.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1395 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1194, 1.0 - _1194), fast::min(_1201, 1.0 - _1201)))), 0.0, 1.0);
    float _1476 = fast::max(dot(_2724, _1013), 9.9999997473787516355514526367188e-05);
    float4 _1541 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1476, params.facet_perceptualRoughness), level(0.0));
    float3 _1560 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1541.y) - 1.0));
    float3 _1741 = fast::normalize(_1013 + frame.lightDirection.xyz);
    float _1662 = fast::clamp(dot(_2724, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1779 = cross(_2724, _1741);
    float _1782 = fast::clamp(dot(_2724, _1741), 0.0, 1.0) * params.facet_alpha;
    float _1791 = params.facet_alpha / fma(_1782, _1782, dot(_1779, _1779));
    float _1804 = params.facet_alpha * params.facet_alpha;
    float _1810 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1814 = sqrt(fma(_1476 * _1476, _1810, _1804));
    float _1837 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1741), 0.0, 1.0);
    float _1840 = _1837 * _1837;
    float3 _1693 = _1386 * 0.3183098733425140380859375;
    float3 _1870 = fma(_1386 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2724.y)) + (frame.sh[2].xyz * _2724.z)) + (frame.sh[3].xyz * _2724.x)) + (((((frame.sh[4].xyz * (_2724.x * _2724.y)) + (frame.sh[5].xyz * (_2724.y * _2724.z))) + (frame.sh[6].xyz * fma(3.0 * _2724.z, _2724.z, -1.0))) + (frame.sh[7].xyz * (_2724.x * _2724.z))) + (frame.sh[8].xyz * fma(_2724.x, _2724.x, -(_2724.y * _2724.y)))), float3(0.0)), fast::max(float3(_1395), ((((((_1386 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1395) + ((_1386 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1395) + ((_1386 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1395), (facet_environment.sample(facet_environmentSmplr, reflect(-_1013, _2724), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1541.xxx, _1541.yyy, float3(0.039999999105930328369140625)) * _1560)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1476 + _1395)) - 1.0) + _1395, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1840 * _1840) * _1837))) * (((_1791 * _1791) * 0.3183098733425140380859375) * (0.5 / fma(_1662, _1814, _1476 * sqrt(fma(_1662 * _1662, _1810, _1804))))), _1560, _1693) * (frame.lightColor.xyz * _1662), float3(65504.0));
    float3 _1905 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1908 = dot(_1905, _1905);
    float3 _1913 = _1905 * rsqrt(fast::max(_1908, 9.9999999392252902907785028219223e-09));
    float _1917 = _1908 * float(frame.punctualLights[0].positionFalloff.w);
    float _1922 = fast::clamp(fma(-_1917, _1917, 1.0), 0.0, 1.0);
    float _1941 = fast::clamp(fma(dot(-_1913, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2080 = fast::normalize(_1013 + _1913);
    float _2001 = fast::clamp(dot(_2724, _1913), 0.0, 1.0);
    float3 _2118 = cross(_2724, _2080);
    float _2121 = fast::clamp(dot(_2724, _2080), 0.0, 1.0) * params.facet_alpha;
    float _2130 = params.facet_alpha / fma(_2121, _2121, dot(_2118, _2118));
    float _2176 = 1.0 - fast::clamp(dot(_1913, _2080), 0.0, 1.0);
    float _2179 = _2176 * _2176;
    float3 _2244 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2247 = dot(_2244, _2244);
    float3 _2252 = _2244 * rsqrt(fast::max(_2247, 9.9999999392252902907785028219223e-09));
    float _2256 = _2247 * float(frame.punctualLights[1].positionFalloff.w);
    float _2261 = fast::clamp(fma(-_2256, _2256, 1.0), 0.0, 1.0);
    float _2280 = fast::clamp(fma(dot(-_2252, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2419 = fast::normalize(_1013 + _2252);
    float _2340 = fast::clamp(dot(_2724, _2252), 0.0, 1.0);
    float3 _2457 = cross(_2724, _2419);
    float _2460 = fast::clamp(dot(_2724, _2419), 0.0, 1.0) * params.facet_alpha;
    float _2469 = params.facet_alpha / fma(_2460, _2460, dot(_2457, _2457));
    float _2515 = 1.0 - fast::clamp(dot(_2252, _2419), 0.0, 1.0);
    float _2518 = _2515 * _2515;
    float3 _2548 = (_1870 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2179 * _2179) * _2176))) * (((_2130 * _2130) * 0.3183098733425140380859375) * (0.5 / fma(_2001, _1814, _1476 * sqrt(fma(_2001 * _2001, _1810, _1804))))), _1560, _1693) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1922 * _1922) / fast::max(_1908, 9.9999997473787516355514526367188e-05)) * _1941) * _1941)) * _2001), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2518 * _2518) * _2515))) * (((_2469 * _2469) * 0.3183098733425140380859375) * (0.5 / fma(_2340, _1814, _1476 * sqrt(fma(_2340 * _2340, _1810, _1804))))), _1560, _1693) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2261 * _2261) / fast::max(_2247, 9.9999997473787516355514526367188e-05)) * _2280) * _2280)) * _2340), float3(65504.0));
    out.fragColor = float4(_2548, 1.0);
    return out;
}

