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
    float3 _1015 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1171 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1174 = facet_material_albedo.sample(facet_material_albedoSmplr, _1171);
    float4 _1184 = facet_material_relief.sample(facet_material_reliefSmplr, _1171);
    float3 _1188 = (_1184.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1194 = fract(_1171 * 4.0);
    float _1196 = _1194.x;
    float _1203 = _1194.y;
    float3 _2728;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2728 = fast::normalize(in.v_normal);
            break;
        }
        _2728 = fast::normalize(((in.v_tangent.xyz * _1188.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1188.y)) + (in.v_normal * _1188.z));
        break;
    } while(false);
    float3 _1388 = fast::clamp(_1174.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1397 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1196, 1.0 - _1196), fast::min(_1203, 1.0 - _1203)))), 0.0, 1.0);
    float _1478 = fast::max(dot(_2728, _1015), 9.9999997473787516355514526367188e-05);
    float4 _1543 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1478, params.facet_perceptualRoughness), level(0.0));
    float3 _1562 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1543.y) - 1.0));
    float3 _1745 = fast::normalize(_1015 + frame.lightDirection.xyz);
    float _1666 = fast::clamp(dot(_2728, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1783 = cross(_2728, _1745);
    float _1786 = fast::clamp(dot(_2728, _1745), 0.0, 1.0) * params.facet_alpha;
    float _1795 = params.facet_alpha / fma(_1786, _1786, dot(_1783, _1783));
    float _1808 = params.facet_alpha * params.facet_alpha;
    float _1814 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1818 = sqrt(fma(_1478 * _1478, _1814, _1808));
    float _1841 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1745), 0.0, 1.0);
    float _1844 = _1841 * _1841;
    float3 _1697 = _1388 * 0.3183098733425140380859375;
    float3 _1874 = fma(_1388 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2728.y)) + (frame.sh[2].xyz * _2728.z)) + (frame.sh[3].xyz * _2728.x)) + (((((frame.sh[4].xyz * (_2728.x * _2728.y)) + (frame.sh[5].xyz * (_2728.y * _2728.z))) + (frame.sh[6].xyz * fma(3.0 * _2728.z, _2728.z, -1.0))) + (frame.sh[7].xyz * (_2728.x * _2728.z))) + (frame.sh[8].xyz * fma(_2728.x, _2728.x, -(_2728.y * _2728.y)))), float3(0.0)), fast::max(float3(_1397), ((((((_1388 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1397) + ((_1388 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1397) + ((_1388 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1397), (facet_environment.sample(facet_environmentSmplr, reflect(-_1015, _2728), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1543.xxx, _1543.yyy, float3(0.039999999105930328369140625)) * _1562)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1478 + _1397)) - 1.0) + _1397, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1844 * _1844) * _1841))) * (((_1795 * _1795) * 0.3183098733425140380859375) * (0.5 / fma(_1666, _1818, _1478 * sqrt(fma(_1666 * _1666, _1814, _1808))))), _1562, _1697) * (frame.lightColor.xyz * _1666), float3(65504.0));
    float3 _1909 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1912 = dot(_1909, _1909);
    float3 _1917 = _1909 * rsqrt(fast::max(_1912, 9.9999999392252902907785028219223e-09));
    float _1921 = _1912 * float(frame.punctualLights[0].positionFalloff.w);
    float _1926 = fast::clamp(fma(-_1921, _1921, 1.0), 0.0, 1.0);
    float _1945 = fast::clamp(fma(dot(-_1917, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2084 = fast::normalize(_1015 + _1917);
    float _2005 = fast::clamp(dot(_2728, _1917), 0.0, 1.0);
    float3 _2122 = cross(_2728, _2084);
    float _2125 = fast::clamp(dot(_2728, _2084), 0.0, 1.0) * params.facet_alpha;
    float _2134 = params.facet_alpha / fma(_2125, _2125, dot(_2122, _2122));
    float _2180 = 1.0 - fast::clamp(dot(_1917, _2084), 0.0, 1.0);
    float _2183 = _2180 * _2180;
    float3 _2248 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2251 = dot(_2248, _2248);
    float3 _2256 = _2248 * rsqrt(fast::max(_2251, 9.9999999392252902907785028219223e-09));
    float _2260 = _2251 * float(frame.punctualLights[1].positionFalloff.w);
    float _2265 = fast::clamp(fma(-_2260, _2260, 1.0), 0.0, 1.0);
    float _2284 = fast::clamp(fma(dot(-_2256, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2423 = fast::normalize(_1015 + _2256);
    float _2344 = fast::clamp(dot(_2728, _2256), 0.0, 1.0);
    float3 _2461 = cross(_2728, _2423);
    float _2464 = fast::clamp(dot(_2728, _2423), 0.0, 1.0) * params.facet_alpha;
    float _2473 = params.facet_alpha / fma(_2464, _2464, dot(_2461, _2461));
    float _2519 = 1.0 - fast::clamp(dot(_2256, _2423), 0.0, 1.0);
    float _2522 = _2519 * _2519;
    float3 _2552 = (_1874 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2183 * _2183) * _2180))) * (((_2134 * _2134) * 0.3183098733425140380859375) * (0.5 / fma(_2005, _1818, _1478 * sqrt(fma(_2005 * _2005, _1814, _1808))))), _1562, _1697) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1926 * _1926) / fast::max(_1912, 9.9999997473787516355514526367188e-05)) * _1945) * _1945)) * _2005), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2522 * _2522) * _2519))) * (((_2473 * _2473) * 0.3183098733425140380859375) * (0.5 / fma(_2344, _1818, _1478 * sqrt(fma(_2344 * _2344, _1814, _1808))))), _1562, _1697) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2265 * _2265) / fast::max(_2251, 9.9999997473787516355514526367188e-05)) * _2284) * _2284)) * _2344), float3(65504.0));
    out.fragColor = float4(_2552, 1.0);
    return out;
}

