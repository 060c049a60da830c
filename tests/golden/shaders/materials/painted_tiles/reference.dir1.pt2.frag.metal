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
    float2 _1011 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1014 = facet_material_albedo.sample(facet_material_albedoSmplr, _1011);
    float4 _1024 = facet_material_relief.sample(facet_material_reliefSmplr, _1011);
    float3 _1028 = (_1024.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _2434;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2434 = fast::normalize(in.v_normal);
            break;
        }
        _2434 = fast::normalize(((in.v_tangent.xyz * _1028.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1028.y)) + (in.v_normal * _1028.z));
        break;
    } while(false);
    float3 _1201 = fast::clamp(_1014.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1236 = fast::max(dot(_2434, _866), 9.9999997473787516355514526367188e-05);
    float4 _1299 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1236, params.facet_perceptualRoughness), level(0.0));
    float3 _1318 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1299.y) - 1.0));
    float3 _1464 = fast::normalize(_866 + frame.lightDirection.xyz);
    float _1385 = fast::clamp(dot(_2434, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1502 = cross(_2434, _1464);
    float _1505 = fast::clamp(dot(_2434, _1464), 0.0, 1.0) * params.facet_alpha;
    float _1514 = params.facet_alpha / fma(_1505, _1505, dot(_1502, _1502));
    float _1527 = params.facet_alpha * params.facet_alpha;
    float _1533 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1537 = sqrt(fma(_1236 * _1236, _1533, _1527));
    float _1560 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1464), 0.0, 1.0);
    float _1563 = _1560 * _1560;
    float3 _1416 = _1201 * 0.3183098733425140380859375;
    float3 _1593 = fma(_1201, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2434.y)) + (frame.sh[2].xyz * _2434.z)) + (frame.sh[3].xyz * _2434.x)) + (((((frame.sh[4].xyz * (_2434.x * _2434.y)) + (frame.sh[5].xyz * (_2434.y * _2434.z))) + (frame.sh[6].xyz * fma(3.0 * _2434.z, _2434.z, -1.0))) + (frame.sh[7].xyz * (_2434.x * _2434.z))) + (frame.sh[8].xyz * fma(_2434.x, _2434.x, -(_2434.y * _2434.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_866, _2434), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1299.xxx, _1299.yyy, float3(0.039999999105930328369140625)) * _1318)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1563 * _1563) * _1560))) * (((_1514 * _1514) * 0.3183098733425140380859375) * (0.5 / fma(_1385, _1537, _1236 * sqrt(fma(_1385 * _1385, _1533, _1527))))), _1318, _1416) * (frame.lightColor.xyz * _1385), float3(65504.0));
    float3 _1628 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1631 = dot(_1628, _1628);
    float3 _1636 = _1628 * rsqrt(fast::max(_1631, 9.9999999392252902907785028219223e-09));
    float _1640 = _1631 * float(frame.punctualLights[0].positionFalloff.w);
    float _1645 = fast::clamp(fma(-_1640, _1640, 1.0), 0.0, 1.0);
    float _1664 = fast::clamp(fma(dot(-_1636, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1803 = fast::normalize(_866 + _1636);
    float _1724 = fast::clamp(dot(_2434, _1636), 0.0, 1.0);
    float3 _1841 = cross(_2434, _1803);
    float _1844 = fast::clamp(dot(_2434, _1803), 0.0, 1.0) * params.facet_alpha;
    float _1853 = params.facet_alpha / fma(_1844, _1844, dot(_1841, _1841));
    float _1899 = 1.0 - fast::clamp(dot(_1636, _1803), 0.0, 1.0);
    float _1902 = _1899 * _1899;
    float3 _1967 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1970 = dot(_1967, _1967);
    float3 _1975 = _1967 * rsqrt(fast::max(_1970, 9.9999999392252902907785028219223e-09));
    float _1979 = _1970 * float(frame.punctualLights[1].positionFalloff.w);
    float _1984 = fast::clamp(fma(-_1979, _1979, 1.0), 0.0, 1.0);
    float _2003 = fast::clamp(fma(dot(-_1975, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2142 = fast::normalize(_866 + _1975);
    float _2063 = fast::clamp(dot(_2434, _1975), 0.0, 1.0);
    float3 _2180 = cross(_2434, _2142);
    float _2183 = fast::clamp(dot(_2434, _2142), 0.0, 1.0) * params.facet_alpha;
    float _2192 = params.facet_alpha / fma(_2183, _2183, dot(_2180, _2180));
    float _2238 = 1.0 - fast::clamp(dot(_1975, _2142), 0.0, 1.0);
    float _2241 = _2238 * _2238;
    float3 _2271 = (_1593 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1902 * _1902) * _1899))) * (((_1853 * _1853) * 0.3183098733425140380859375) * (0.5 / fma(_1724, _1537, _1236 * sqrt(fma(_1724 * _1724, _1533, _1527))))), _1318, _1416) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1645 * _1645) / fast::max(_1631, 9.9999997473787516355514526367188e-05)) * _1664) * _1664)) * _1724), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2241 * _2241) * _2238))) * (((_2192 * _2192) * 0.3183098733425140380859375) * (0.5 / fma(_2063, _1537, _1236 * sqrt(fma(_2063 * _2063, _1533, _1527))))), _1318, _1416) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1984 * _1984) / fast::max(_1970, 9.9999997473787516355514526367188e-05)) * _2003) * _2003)) * _2063), float3(65504.0));
    out.fragColor = float4(_2271, 1.0);
    return out;
}

