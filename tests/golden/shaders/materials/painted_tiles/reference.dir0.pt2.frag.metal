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
    float3 _1031 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1166 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1169 = facet_material_albedo.sample(facet_material_albedoSmplr, _1166);
    float4 _1179 = facet_material_relief.sample(facet_material_reliefSmplr, _1166);
    float3 _1183 = (_1179.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1189 = fract(_1166 * 4.0);
    float _1191 = _1189.x;
    float _1198 = _1189.y;
    float3 _2472;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2472 = fast::normalize(in.v_normal);
            break;
        }
        _2472 = fast::normalize(((in.v_tangent.xyz * _1183.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1183.y)) + (in.v_normal * _1183.z));
        break;
    } while(false);
    float3 _1383 = fast::clamp(_1169.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1392 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1191, 1.0 - _1191), fast::min(_1198, 1.0 - _1198)))), 0.0, 1.0);
    float _1473 = fast::max(dot(_2472, _1031), 9.9999997473787516355514526367188e-05);
    float4 _1538 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1473, params.facet_perceptualRoughness), level(0.0));
    float3 _1557 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1538.y) - 1.0));
    float3 _1643 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1646 = dot(_1643, _1643);
    float3 _1651 = _1643 * rsqrt(fast::max(_1646, 9.9999999392252902907785028219223e-09));
    float _1655 = _1646 * float(frame.punctualLights[0].positionFalloff.w);
    float _1660 = fast::clamp(fma(-_1655, _1655, 1.0), 0.0, 1.0);
    float _1679 = fast::clamp(fma(dot(-_1651, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1818 = fast::normalize(_1031 + _1651);
    float _1739 = fast::clamp(dot(_2472, _1651), 0.0, 1.0);
    float _1856 = 4096.0 * params.facet_alpha;
    float4 _1880 = float4(cross(_2472, _1818), params.facet_alpha * fast::clamp(dot(_2472, _1818), 0.0, 1.0)) * 64.0;
    float _1862 = _1856 / dot(_1880, _1880);
    float _1891 = params.facet_alpha * params.facet_alpha;
    float _1897 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1901 = sqrt(fma(_1473 * _1473, _1897, _1891));
    float _1924 = 1.0 - fast::clamp(dot(_1651, _1818), 0.0, 1.0);
    float _1927 = _1924 * _1924;
    float3 _1770 = _1383 * 0.3183098733425140380859375;
    float3 _1957 = fma(_1383 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2472.y)) + (frame.sh[2].xyz * _2472.z)) + (frame.sh[3].xyz * _2472.x)) + (((((frame.sh[4].xyz * (_2472.x * _2472.y)) + (frame.sh[5].xyz * (_2472.y * _2472.z))) + (frame.sh[6].xyz * fma(3.0 * _2472.z, _2472.z, -1.0))) + (frame.sh[7].xyz * (_2472.x * _2472.z))) + (frame.sh[8].xyz * fma(_2472.x, _2472.x, -(_2472.y * _2472.y)))), float3(0.0)), fast::max(float3(_1392), ((((((_1383 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1392) + ((_1383 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1392) + ((_1383 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1392), (facet_environment.sample(facet_environmentSmplr, reflect(-_1031, _2472), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1538.xxx, _1538.yyy, float3(0.039999999105930328369140625)) * _1557)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1473 + _1392)) - 1.0) + _1392, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1927 * _1927) * _1924))) * (((_1862 * _1862) * 0.3183098733425140380859375) * (0.5 / fma(_1739, _1901, _1473 * sqrt(fma(_1739 * _1739, _1897, _1891))))), _1557, _1770) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1660 * _1660) / fast::max(_1646, 9.9999997473787516355514526367188e-05)) * _1679) * _1679)) * _1739), float3(65504.0));
    float3 _1992 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1995 = dot(_1992, _1992);
    float3 _2000 = _1992 * rsqrt(fast::max(_1995, 9.9999999392252902907785028219223e-09));
    float _2004 = _1995 * float(frame.punctualLights[1].positionFalloff.w);
    float _2009 = fast::clamp(fma(-_2004, _2004, 1.0), 0.0, 1.0);
    float _2028 = fast::clamp(fma(dot(-_2000, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2167 = fast::normalize(_1031 + _2000);
    float _2088 = fast::clamp(dot(_2472, _2000), 0.0, 1.0);
    float4 _2229 = float4(cross(_2472, _2167), params.facet_alpha * fast::clamp(dot(_2472, _2167), 0.0, 1.0)) * 64.0;
    float _2211 = _1856 / dot(_2229, _2229);
    float _2273 = 1.0 - fast::clamp(dot(_2000, _2167), 0.0, 1.0);
    float _2276 = _2273 * _2273;
    out.fragColor = float4(_1957 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2276 * _2276) * _2273))) * (((_2211 * _2211) * 0.3183098733425140380859375) * (0.5 / fma(_2088, _1901, _1473 * sqrt(fma(_2088 * _2088, _1897, _1891))))), _1557, _1770) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2009 * _2009) / fast::max(_1995, 9.9999997473787516355514526367188e-05)) * _2028) * _2028)) * _2088), float3(65504.0)), 1.0);
    return out;
}

