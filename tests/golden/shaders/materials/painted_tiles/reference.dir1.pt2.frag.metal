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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _1017 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1173 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1176 = facet_material_albedo.sample(facet_material_albedoSmplr, _1173);
    float4 _1186 = facet_material_relief.sample(facet_material_reliefSmplr, _1173);
    float3 _1190 = (_1186.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1196 = fract(_1173 * 4.0);
    float _1198 = _1196.x;
    float _1205 = _1196.y;
    float3 _2748;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2748 = fast::normalize(in.v_normal);
            break;
        }
        _2748 = fast::normalize(((in.v_tangent.xyz * _1190.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1190.y)) + (in.v_normal * _1190.z));
        break;
    } while(false);
    float3 _1390 = fast::clamp(_1176.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1399 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1198, 1.0 - _1198), fast::min(_1205, 1.0 - _1205)))), 0.0, 1.0);
    float _1478 = fast::max(dot(_2748, _1017), 9.9999997473787516355514526367188e-05);
    float4 _1546 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1478, params.facet_perceptualRoughness), level(0.0));
    float3 _1565 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1546.y) - 1.0));
    float _1653 = fast::clamp(dot(_2748, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1735 = fast::normalize(_1017 + frame.lightDirection.xyz);
    float _1773 = 4096.0 * params.facet_alpha;
    float4 _1797 = float4(cross(_2748, _1735), params.facet_alpha * fast::clamp(dot(_2748, _1735), 0.0, 1.0)) * 64.0;
    float _1779 = _1773 / dot(_1797, _1797);
    float _1808 = params.facet_alpha * params.facet_alpha;
    float _1814 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1818 = sqrt(fma(_1478 * _1478, _1814, _1808));
    float _1841 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1735), 0.0, 1.0);
    float _1844 = _1841 * _1841;
    float3 _1687 = _1390 * 0.3183098733425140380859375;
    float3 _1874 = fma(_1390 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2748.y)) + (frame.sh[2].xyz * _2748.z)) + (frame.sh[3].xyz * _2748.x)) + (((((frame.sh[4].xyz * (_2748.x * _2748.y)) + (frame.sh[5].xyz * (_2748.y * _2748.z))) + (frame.sh[6].xyz * fma(3.0 * _2748.z, _2748.z, -1.0))) + (frame.sh[7].xyz * (_2748.x * _2748.z))) + (frame.sh[8].xyz * fma(_2748.x, _2748.x, -(_2748.y * _2748.y)))), float3(0.0)), fast::max(float3(_1399), ((((((_1390 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1399) + ((_1390 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1399) + ((_1390 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1399), (facet_environment.sample(facet_environmentSmplr, reflect(-_1017, _2748), level(params.facet_environmentLod)).xyz * (mix(_1546.xxx, _1546.yyy, float3(0.039999999105930328369140625)) * _1565)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1478 + _1399)) - 1.0) + _1399, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1844 * _1844) * _1841))) * (((_1779 * _1779) * 0.3183098733425140380859375) * (0.5 / fma(_1653, _1818, _1478 * sqrt(fma(_1653 * _1653, _1814, _1808))))), _1565, _1687) * (frame.lightColor.xyz * _1653), float3(65504.0));
    float3 _1909 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1912 = dot(_1909, _1909);
    float3 _1917 = _1909 * rsqrt(fast::max(_1912, 9.9999999392252902907785028219223e-09));
    float _1921 = _1912 * float(frame.punctualLights[0].positionFalloff.w);
    float _1926 = fast::clamp(fma(-_1921, _1921, 1.0), 0.0, 1.0);
    float _1945 = fast::clamp(fma(dot(-_1917, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _2002 = fast::clamp(dot(_2748, _1917), 0.0, 1.0);
    float3 _2084 = fast::normalize(_1017 + _1917);
    float4 _2146 = float4(cross(_2748, _2084), params.facet_alpha * fast::clamp(dot(_2748, _2084), 0.0, 1.0)) * 64.0;
    float _2128 = _1773 / dot(_2146, _2146);
    float _2190 = 1.0 - fast::clamp(dot(_1917, _2084), 0.0, 1.0);
    float _2193 = _2190 * _2190;
    float3 _2258 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2261 = dot(_2258, _2258);
    float3 _2266 = _2258 * rsqrt(fast::max(_2261, 9.9999999392252902907785028219223e-09));
    float _2270 = _2261 * float(frame.punctualLights[1].positionFalloff.w);
    float _2275 = fast::clamp(fma(-_2270, _2270, 1.0), 0.0, 1.0);
    float _2294 = fast::clamp(fma(dot(-_2266, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _2351 = fast::clamp(dot(_2748, _2266), 0.0, 1.0);
    float3 _2433 = fast::normalize(_1017 + _2266);
    float4 _2495 = float4(cross(_2748, _2433), params.facet_alpha * fast::clamp(dot(_2748, _2433), 0.0, 1.0)) * 64.0;
    float _2477 = _1773 / dot(_2495, _2495);
    float _2539 = 1.0 - fast::clamp(dot(_2266, _2433), 0.0, 1.0);
    float _2542 = _2539 * _2539;
    float3 _2572 = (_1874 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2193 * _2193) * _2190))) * (((_2128 * _2128) * 0.3183098733425140380859375) * (0.5 / fma(_2002, _1818, _1478 * sqrt(fma(_2002 * _2002, _1814, _1808))))), _1565, _1687) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1926 * _1926) / fast::max(_1912, 9.9999997473787516355514526367188e-05)) * _1945) * _1945)) * _2002), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2542 * _2542) * _2539))) * (((_2477 * _2477) * 0.3183098733425140380859375) * (0.5 / fma(_2351, _1818, _1478 * sqrt(fma(_2351 * _2351, _1814, _1808))))), _1565, _1687) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2275 * _2275) / fast::max(_2261, 9.9999997473787516355514526367188e-05)) * _2294) * _2294)) * _2351), float3(65504.0));
    out.fragColor = float4(_2572, 1.0);
    return out;
}

