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
    float2 _990 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _993 = facet_material_albedo.sample(facet_material_albedoSmplr, _990);
    float4 _1003 = facet_material_relief.sample(facet_material_reliefSmplr, _990);
    float3 _1007 = (_1003.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2144;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2144 = fast::normalize(in.v_normal);
            break;
        }
        _2144 = fast::normalize(((in.v_tangent.xyz * _1007.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1007.y)) + (in.v_normal * _1007.z));
        break;
    } while(false);
    float3 _1180 = fast::clamp(_993.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1215 = fast::max(dot(_2144, _866), 9.9999997473787516355514526367188e-05);
    float4 _1278 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1215, params.facet_perceptualRoughness), level(0.0));
    float3 _1297 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1278.y) - 1.0));
    float3 _1348 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1351 = dot(_1348, _1348);
    float3 _1356 = _1348 * rsqrt(fast::max(_1351, 9.9999999392252902907785028219223e-09));
    float _1360 = _1351 * float(frame.punctualLights[0].positionFalloff.w);
    float _1365 = fast::clamp(fma(-_1360, _1360, 1.0), 0.0, 1.0);
    float _1384 = fast::clamp(fma(dot(-_1356, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1523 = fast::normalize(_866 + _1356);
    float _1444 = fast::clamp(dot(_2144, _1356), 0.0, 1.0);
    float3 _1561 = cross(_2144, _1523);
    float _1564 = fast::clamp(dot(_2144, _1523), 0.0, 1.0) * params.facet_alpha;
    float _1573 = params.facet_alpha / fma(_1564, _1564, dot(_1561, _1561));
    float _1586 = params.facet_alpha * params.facet_alpha;
    float _1592 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1596 = sqrt(fma(_1215 * _1215, _1592, _1586));
    float _1619 = 1.0 - fast::clamp(dot(_1356, _1523), 0.0, 1.0);
    float _1622 = _1619 * _1619;
    float3 _1475 = _1180 * 0.3183098733425140380859375;
    float3 _1652 = fma(_1180, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2144.y)) + (frame.sh[2].xyz * _2144.z)) + (frame.sh[3].xyz * _2144.x)) + (((((frame.sh[4].xyz * (_2144.x * _2144.y)) + (frame.sh[5].xyz * (_2144.y * _2144.z))) + (frame.sh[6].xyz * fma(3.0 * _2144.z, _2144.z, -1.0))) + (frame.sh[7].xyz * (_2144.x * _2144.z))) + (frame.sh[8].xyz * fma(_2144.x, _2144.x, -(_2144.y * _2144.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_866, _2144), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1278.xxx, _1278.yyy, float3(0.039999999105930328369140625)) * _1297)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1622 * _1622) * _1619))) * (((_1573 * _1573) * 0.3183098733425140380859375) * (0.5 / fma(_1444, _1596, _1215 * sqrt(fma(_1444 * _1444, _1592, _1586))))), _1297, _1475) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1365 * _1365) / fast::max(_1351, 9.9999997473787516355514526367188e-05)) * _1384) * _1384)) * _1444), float3(65504.0));
    float3 _1687 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1690 = dot(_1687, _1687);
    float3 _1695 = _1687 * rsqrt(fast::max(_1690, 9.9999999392252902907785028219223e-09));
    float _1699 = _1690 * float(frame.punctualLights[1].positionFalloff.w);
    float _1704 = fast::clamp(fma(-_1699, _1699, 1.0), 0.0, 1.0);
    float _1723 = fast::clamp(fma(dot(-_1695, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1862 = fast::normalize(_866 + _1695);
    float _1783 = fast::clamp(dot(_2144, _1695), 0.0, 1.0);
    float3 _1900 = cross(_2144, _1862);
    float _1903 = fast::clamp(dot(_2144, _1862), 0.0, 1.0) * params.facet_alpha;
    float _1912 = params.facet_alpha / fma(_1903, _1903, dot(_1900, _1900));
    float _1958 = 1.0 - fast::clamp(dot(_1695, _1862), 0.0, 1.0);
    float _1961 = _1958 * _1958;
    out.fragColor = float4(_1652 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1961 * _1961) * _1958))) * (((_1912 * _1912) * 0.3183098733425140380859375) * (0.5 / fma(_1783, _1596, _1215 * sqrt(fma(_1783 * _1783, _1592, _1586))))), _1297, _1475) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1704 * _1704) / fast::max(_1690, 9.9999997473787516355514526367188e-05)) * _1723) * _1723)) * _1783), float3(65504.0)), 1.0);
    return out;
}

