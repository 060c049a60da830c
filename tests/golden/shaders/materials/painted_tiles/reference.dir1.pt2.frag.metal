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
    float3 _866 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1014 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1017 = facet_material_albedo.sample(facet_material_albedoSmplr, _1014);
    float4 _1027 = facet_material_relief.sample(facet_material_reliefSmplr, _1014);
    float3 _1031 = (_1027.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2437;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2437 = fast::normalize(in.v_normal);
            break;
        }
        _2437 = fast::normalize(((in.v_tangent.xyz * _1031.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1031.y)) + (in.v_normal * _1031.z));
        break;
    } while(false);
    float3 _1204 = fast::clamp(_1017.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1239 = fast::max(dot(_2437, _866), 9.9999997473787516355514526367188e-05);
    float4 _1302 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1239, params.facet_perceptualRoughness), level(0.0));
    float3 _1321 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1302.y) - 1.0));
    float3 _1467 = fast::normalize(_866 + frame.lightDirection.xyz);
    float _1388 = fast::clamp(dot(_2437, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1505 = cross(_2437, _1467);
    float _1508 = fast::clamp(dot(_2437, _1467), 0.0, 1.0) * params.facet_alpha;
    float _1517 = params.facet_alpha / fma(_1508, _1508, dot(_1505, _1505));
    float _1530 = params.facet_alpha * params.facet_alpha;
    float _1536 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1540 = sqrt(fma(_1239 * _1239, _1536, _1530));
    float _1563 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1467), 0.0, 1.0);
    float _1566 = _1563 * _1563;
    float3 _1419 = _1204 * 0.3183098733425140380859375;
    float3 _1596 = fma(_1204, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2437.y)) + (frame.sh[2].xyz * _2437.z)) + (frame.sh[3].xyz * _2437.x)) + (((((frame.sh[4].xyz * (_2437.x * _2437.y)) + (frame.sh[5].xyz * (_2437.y * _2437.z))) + (frame.sh[6].xyz * fma(3.0 * _2437.z, _2437.z, -1.0))) + (frame.sh[7].xyz * (_2437.x * _2437.z))) + (frame.sh[8].xyz * fma(_2437.x, _2437.x, -(_2437.y * _2437.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_866, _2437), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1302.xxx, _1302.yyy, float3(0.039999999105930328369140625)) * _1321)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1566 * _1566) * _1563))) * (((_1517 * _1517) * 0.3183098733425140380859375) * (0.5 / fma(_1388, _1540, _1239 * sqrt(fma(_1388 * _1388, _1536, _1530))))), _1321, _1419) * (frame.lightColor.xyz * _1388), float3(65504.0));
    float3 _1631 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1634 = dot(_1631, _1631);
    float3 _1639 = _1631 * rsqrt(fast::max(_1634, 9.9999999392252902907785028219223e-09));
    float _1643 = _1634 * float(frame.punctualLights[0].positionFalloff.w);
    float _1648 = fast::clamp(fma(-_1643, _1643, 1.0), 0.0, 1.0);
    float _1667 = fast::clamp(fma(dot(-_1639, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1806 = fast::normalize(_866 + _1639);
    float _1727 = fast::clamp(dot(_2437, _1639), 0.0, 1.0);
    float3 _1844 = cross(_2437, _1806);
    float _1847 = fast::clamp(dot(_2437, _1806), 0.0, 1.0) * params.facet_alpha;
    float _1856 = params.facet_alpha / fma(_1847, _1847, dot(_1844, _1844));
    float _1902 = 1.0 - fast::clamp(dot(_1639, _1806), 0.0, 1.0);
    float _1905 = _1902 * _1902;
    float3 _1970 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1973 = dot(_1970, _1970);
    float3 _1978 = _1970 * rsqrt(fast::max(_1973, 9.9999999392252902907785028219223e-09));
    float _1982 = _1973 * float(frame.punctualLights[1].positionFalloff.w);
    float _1987 = fast::clamp(fma(-_1982, _1982, 1.0), 0.0, 1.0);
    float _2006 = fast::clamp(fma(dot(-_1978, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2145 = fast::normalize(_866 + _1978);
    float _2066 = fast::clamp(dot(_2437, _1978), 0.0, 1.0);
    float3 _2183 = cross(_2437, _2145);
    float _2186 = fast::clamp(dot(_2437, _2145), 0.0, 1.0) * params.facet_alpha;
    float _2195 = params.facet_alpha / fma(_2186, _2186, dot(_2183, _2183));
    float _2241 = 1.0 - fast::clamp(dot(_1978, _2145), 0.0, 1.0);
    float _2244 = _2241 * _2241;
    float3 _2274 = (_1596 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1905 * _1905) * _1902))) * (((_1856 * _1856) * 0.3183098733425140380859375) * (0.5 / fma(_1727, _1540, _1239 * sqrt(fma(_1727 * _1727, _1536, _1530))))), _1321, _1419) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1648 * _1648) / fast::max(_1634, 9.9999997473787516355514526367188e-05)) * _1667) * _1667)) * _1727), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2244 * _2244) * _2241))) * (((_2195 * _2195) * 0.3183098733425140380859375) * (0.5 / fma(_2066, _1540, _1239 * sqrt(fma(_2066 * _2066, _1536, _1530))))), _1321, _1419) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1987 * _1987) / fast::max(_1973, 9.9999997473787516355514526367188e-05)) * _2006) * _2006)) * _2066), float3(65504.0));
    out.fragColor = float4(_2274, 1.0);
    return out;
}

