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
    float2 _993 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _996 = facet_material_albedo.sample(facet_material_albedoSmplr, _993);
    float4 _1006 = facet_material_relief.sample(facet_material_reliefSmplr, _993);
    float3 _1010 = (_1006.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2147;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2147 = fast::normalize(in.v_normal);
            break;
        }
        _2147 = fast::normalize(((in.v_tangent.xyz * _1010.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1010.y)) + (in.v_normal * _1010.z));
        break;
    } while(false);
    float3 _1183 = fast::clamp(_996.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1218 = fast::max(dot(_2147, _866), 9.9999997473787516355514526367188e-05);
    float4 _1281 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1218, params.facet_perceptualRoughness), level(0.0));
    float3 _1300 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1281.y) - 1.0));
    float3 _1351 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1354 = dot(_1351, _1351);
    float3 _1359 = _1351 * rsqrt(fast::max(_1354, 9.9999999392252902907785028219223e-09));
    float _1363 = _1354 * float(frame.punctualLights[0].positionFalloff.w);
    float _1368 = fast::clamp(fma(-_1363, _1363, 1.0), 0.0, 1.0);
    float _1387 = fast::clamp(fma(dot(-_1359, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1526 = fast::normalize(_866 + _1359);
    float _1447 = fast::clamp(dot(_2147, _1359), 0.0, 1.0);
    float3 _1564 = cross(_2147, _1526);
    float _1567 = fast::clamp(dot(_2147, _1526), 0.0, 1.0) * params.facet_alpha;
    float _1576 = params.facet_alpha / fma(_1567, _1567, dot(_1564, _1564));
    float _1589 = params.facet_alpha * params.facet_alpha;
    float _1595 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1599 = sqrt(fma(_1218 * _1218, _1595, _1589));
    float _1622 = 1.0 - fast::clamp(dot(_1359, _1526), 0.0, 1.0);
    float _1625 = _1622 * _1622;
    float3 _1478 = _1183 * 0.3183098733425140380859375;
    float3 _1655 = fma(_1183, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2147.y)) + (frame.sh[2].xyz * _2147.z)) + (frame.sh[3].xyz * _2147.x)) + (((((frame.sh[4].xyz * (_2147.x * _2147.y)) + (frame.sh[5].xyz * (_2147.y * _2147.z))) + (frame.sh[6].xyz * fma(3.0 * _2147.z, _2147.z, -1.0))) + (frame.sh[7].xyz * (_2147.x * _2147.z))) + (frame.sh[8].xyz * fma(_2147.x, _2147.x, -(_2147.y * _2147.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_866, _2147), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1281.xxx, _1281.yyy, float3(0.039999999105930328369140625)) * _1300)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1625 * _1625) * _1622))) * (((_1576 * _1576) * 0.3183098733425140380859375) * (0.5 / fma(_1447, _1599, _1218 * sqrt(fma(_1447 * _1447, _1595, _1589))))), _1300, _1478) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1368 * _1368) / fast::max(_1354, 9.9999997473787516355514526367188e-05)) * _1387) * _1387)) * _1447), float3(65504.0));
    float3 _1690 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1693 = dot(_1690, _1690);
    float3 _1698 = _1690 * rsqrt(fast::max(_1693, 9.9999999392252902907785028219223e-09));
    float _1702 = _1693 * float(frame.punctualLights[1].positionFalloff.w);
    float _1707 = fast::clamp(fma(-_1702, _1702, 1.0), 0.0, 1.0);
    float _1726 = fast::clamp(fma(dot(-_1698, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1865 = fast::normalize(_866 + _1698);
    float _1786 = fast::clamp(dot(_2147, _1698), 0.0, 1.0);
    float3 _1903 = cross(_2147, _1865);
    float _1906 = fast::clamp(dot(_2147, _1865), 0.0, 1.0) * params.facet_alpha;
    float _1915 = params.facet_alpha / fma(_1906, _1906, dot(_1903, _1903));
    float _1961 = 1.0 - fast::clamp(dot(_1698, _1865), 0.0, 1.0);
    float _1964 = _1961 * _1961;
    out.fragColor = float4(_1655 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1964 * _1964) * _1961))) * (((_1915 * _1915) * 0.3183098733425140380859375) * (0.5 / fma(_1786, _1599, _1218 * sqrt(fma(_1786 * _1786, _1595, _1589))))), _1300, _1478) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1707 * _1707) / fast::max(_1693, 9.9999997473787516355514526367188e-05)) * _1726) * _1726)) * _1786), float3(65504.0)), 1.0);
    return out;
}

