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
    float3 _1032 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1188 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1191 = facet_material_albedo.sample(facet_material_albedoSmplr, _1188);
    float4 _1201 = facet_material_relief.sample(facet_material_reliefSmplr, _1188);
    float3 _1205 = (_1201.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1211 = fract(_1188 * 4.0);
    float _1213 = _1211.x;
    float _1220 = _1211.y;
    float3 _2782;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2782 = fast::normalize(in.v_normal);
            break;
        }
        _2782 = fast::normalize(((in.v_tangent.xyz * _1205.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1205.y)) + (in.v_normal * _1205.z));
        break;
    } while(false);
    float3 _1405 = fast::clamp(_1191.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1414 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1213, 1.0 - _1213), fast::min(_1220, 1.0 - _1220)))), 0.0, 1.0);
    float _1495 = fast::max(dot(_2782, _1032), 9.9999997473787516355514526367188e-05);
    float4 _1560 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1495, params.facet_perceptualRoughness), level(0.0));
    float3 _1579 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1560.y) - 1.0));
    float3 _1757 = fast::normalize(_1032 + frame.lightDirection.xyz);
    float _1678 = fast::clamp(dot(_2782, frame.lightDirection.xyz), 0.0, 1.0);
    float _1796 = 4096.0 * params.facet_alpha;
    float3 _1815 = cross(_2782, _1757) * 64.0;
    float _1818 = 64.0 * params.facet_alpha;
    float _1819 = fast::clamp(dot(_2782, _1757), 0.0, 1.0) * _1818;
    float _1802 = _1796 / fma(_1819, _1819, dot(_1815, _1815));
    float _1834 = params.facet_alpha * params.facet_alpha;
    float _1840 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1844 = sqrt(fma(_1495 * _1495, _1840, _1834));
    float _1867 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1757), 0.0, 1.0);
    float _1870 = _1867 * _1867;
    float3 _1709 = _1405 * 0.3183098733425140380859375;
    float3 _1900 = fma(_1405 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2782.y)) + (frame.sh[2].xyz * _2782.z)) + (frame.sh[3].xyz * _2782.x)) + (((((frame.sh[4].xyz * (_2782.x * _2782.y)) + (frame.sh[5].xyz * (_2782.y * _2782.z))) + (frame.sh[6].xyz * fma(3.0 * _2782.z, _2782.z, -1.0))) + (frame.sh[7].xyz * (_2782.x * _2782.z))) + (frame.sh[8].xyz * fma(_2782.x, _2782.x, -(_2782.y * _2782.y)))), float3(0.0)), fast::max(float3(_1414), ((((((_1405 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1414) + ((_1405 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1414) + ((_1405 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1414), (facet_environment.sample(facet_environmentSmplr, reflect(-_1032, _2782), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1560.xxx, _1560.yyy, float3(0.039999999105930328369140625)) * _1579)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1495 + _1414)) - 1.0) + _1414, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1870 * _1870) * _1867))) * (((_1802 * _1802) * 0.3183098733425140380859375) * (0.5 / fma(_1678, _1844, _1495 * sqrt(fma(_1678 * _1678, _1840, _1834))))), _1579, _1709) * (frame.lightColor.xyz * _1678), float3(65504.0));
    float3 _1935 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1938 = dot(_1935, _1935);
    float3 _1943 = _1935 * rsqrt(fast::max(_1938, 9.9999999392252902907785028219223e-09));
    float _1947 = _1938 * float(frame.punctualLights[0].positionFalloff.w);
    float _1952 = fast::clamp(fma(-_1947, _1947, 1.0), 0.0, 1.0);
    float _1971 = fast::clamp(fma(dot(-_1943, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2110 = fast::normalize(_1032 + _1943);
    float _2031 = fast::clamp(dot(_2782, _1943), 0.0, 1.0);
    float3 _2168 = cross(_2782, _2110) * 64.0;
    float _2172 = fast::clamp(dot(_2782, _2110), 0.0, 1.0) * _1818;
    float _2155 = _1796 / fma(_2172, _2172, dot(_2168, _2168));
    float _2220 = 1.0 - fast::clamp(dot(_1943, _2110), 0.0, 1.0);
    float _2223 = _2220 * _2220;
    float3 _2288 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2291 = dot(_2288, _2288);
    float3 _2296 = _2288 * rsqrt(fast::max(_2291, 9.9999999392252902907785028219223e-09));
    float _2300 = _2291 * float(frame.punctualLights[1].positionFalloff.w);
    float _2305 = fast::clamp(fma(-_2300, _2300, 1.0), 0.0, 1.0);
    float _2324 = fast::clamp(fma(dot(-_2296, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2463 = fast::normalize(_1032 + _2296);
    float _2384 = fast::clamp(dot(_2782, _2296), 0.0, 1.0);
    float3 _2521 = cross(_2782, _2463) * 64.0;
    float _2525 = fast::clamp(dot(_2782, _2463), 0.0, 1.0) * _1818;
    float _2508 = _1796 / fma(_2525, _2525, dot(_2521, _2521));
    float _2573 = 1.0 - fast::clamp(dot(_2296, _2463), 0.0, 1.0);
    float _2576 = _2573 * _2573;
    float3 _2606 = (_1900 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2223 * _2223) * _2220))) * (((_2155 * _2155) * 0.3183098733425140380859375) * (0.5 / fma(_2031, _1844, _1495 * sqrt(fma(_2031 * _2031, _1840, _1834))))), _1579, _1709) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1952 * _1952) / fast::max(_1938, 9.9999997473787516355514526367188e-05)) * _1971) * _1971)) * _2031), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2576 * _2576) * _2573))) * (((_2508 * _2508) * 0.3183098733425140380859375) * (0.5 / fma(_2384, _1844, _1495 * sqrt(fma(_2384 * _2384, _1840, _1834))))), _1579, _1709) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2305 * _2305) / fast::max(_2291, 9.9999997473787516355514526367188e-05)) * _2324) * _2324)) * _2384), float3(65504.0));
    out.fragColor = float4(_2606, 1.0);
    return out;
}

