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
    float2 _1167 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1170 = facet_material_albedo.sample(facet_material_albedoSmplr, _1167);
    float4 _1180 = facet_material_relief.sample(facet_material_reliefSmplr, _1167);
    float3 _1184 = (_1180.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1190 = fract(_1167 * 4.0);
    float _1192 = _1190.x;
    float _1199 = _1190.y;
    float3 _2478;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2478 = fast::normalize(in.v_normal);
            break;
        }
        _2478 = fast::normalize(((in.v_tangent.xyz * _1184.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1184.y)) + (in.v_normal * _1184.z));
        break;
    } while(false);
    float3 _1384 = fast::clamp(_1170.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1393 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1192, 1.0 - _1192), fast::min(_1199, 1.0 - _1199)))), 0.0, 1.0);
    float _1474 = fast::max(dot(_2478, _1032), 9.9999997473787516355514526367188e-05);
    float4 _1539 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1474, params.facet_perceptualRoughness), level(0.0));
    float3 _1558 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1539.y) - 1.0));
    float3 _1641 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1644 = dot(_1641, _1641);
    float3 _1649 = _1641 * rsqrt(fast::max(_1644, 9.9999999392252902907785028219223e-09));
    float _1653 = _1644 * float(frame.punctualLights[0].positionFalloff.w);
    float _1658 = fast::clamp(fma(-_1653, _1653, 1.0), 0.0, 1.0);
    float _1677 = fast::clamp(fma(dot(-_1649, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1816 = fast::normalize(_1032 + _1649);
    float _1737 = fast::clamp(dot(_2478, _1649), 0.0, 1.0);
    float _1855 = 4096.0 * params.facet_alpha;
    float3 _1874 = cross(_2478, _1816) * 64.0;
    float _1877 = 64.0 * params.facet_alpha;
    float _1878 = fast::clamp(dot(_2478, _1816), 0.0, 1.0) * _1877;
    float _1861 = _1855 / fma(_1878, _1878, dot(_1874, _1874));
    float _1893 = params.facet_alpha * params.facet_alpha;
    float _1899 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1903 = sqrt(fma(_1474 * _1474, _1899, _1893));
    float _1926 = 1.0 - fast::clamp(dot(_1649, _1816), 0.0, 1.0);
    float _1929 = _1926 * _1926;
    float3 _1768 = _1384 * 0.3183098733425140380859375;
    float3 _1959 = fma(_1384 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2478.y)) + (frame.sh[2].xyz * _2478.z)) + (frame.sh[3].xyz * _2478.x)) + (((((frame.sh[4].xyz * (_2478.x * _2478.y)) + (frame.sh[5].xyz * (_2478.y * _2478.z))) + (frame.sh[6].xyz * fma(3.0 * _2478.z, _2478.z, -1.0))) + (frame.sh[7].xyz * (_2478.x * _2478.z))) + (frame.sh[8].xyz * fma(_2478.x, _2478.x, -(_2478.y * _2478.y)))), float3(0.0)), fast::max(float3(_1393), ((((((_1384 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1393) + ((_1384 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1393) + ((_1384 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1393), (facet_environment.sample(facet_environmentSmplr, reflect(-_1032, _2478), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1539.xxx, _1539.yyy, float3(0.039999999105930328369140625)) * _1558)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1474 + _1393)) - 1.0) + _1393, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1929 * _1929) * _1926))) * (((_1861 * _1861) * 0.3183098733425140380859375) * (0.5 / fma(_1737, _1903, _1474 * sqrt(fma(_1737 * _1737, _1899, _1893))))), _1558, _1768) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1658 * _1658) / fast::max(_1644, 9.9999997473787516355514526367188e-05)) * _1677) * _1677)) * _1737), float3(65504.0));
    float3 _1994 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1997 = dot(_1994, _1994);
    float3 _2002 = _1994 * rsqrt(fast::max(_1997, 9.9999999392252902907785028219223e-09));
    float _2006 = _1997 * float(frame.punctualLights[1].positionFalloff.w);
    float _2011 = fast::clamp(fma(-_2006, _2006, 1.0), 0.0, 1.0);
    float _2030 = fast::clamp(fma(dot(-_2002, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2169 = fast::normalize(_1032 + _2002);
    float _2090 = fast::clamp(dot(_2478, _2002), 0.0, 1.0);
    float3 _2227 = cross(_2478, _2169) * 64.0;
    float _2231 = fast::clamp(dot(_2478, _2169), 0.0, 1.0) * _1877;
    float _2214 = _1855 / fma(_2231, _2231, dot(_2227, _2227));
    float _2279 = 1.0 - fast::clamp(dot(_2002, _2169), 0.0, 1.0);
    float _2282 = _2279 * _2279;
    out.fragColor = float4(_1959 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2282 * _2282) * _2279))) * (((_2214 * _2214) * 0.3183098733425140380859375) * (0.5 / fma(_2090, _1903, _1474 * sqrt(fma(_2090 * _2090, _1899, _1893))))), _1558, _1768) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2011 * _2011) / fast::max(_1997, 9.9999997473787516355514526367188e-05)) * _2030) * _2030)) * _2090), float3(65504.0)), 1.0);
    return out;
}

