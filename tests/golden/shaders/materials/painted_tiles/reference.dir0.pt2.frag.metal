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
    float2 _1152 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1155 = facet_material_albedo.sample(facet_material_albedoSmplr, _1152);
    float4 _1165 = facet_material_relief.sample(facet_material_reliefSmplr, _1152);
    float3 _1169 = (_1165.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1175 = fract(_1152 * 4.0);
    float _1177 = _1175.x;
    float _1184 = _1175.y;
    float3 _2448;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2448 = fast::normalize(in.v_normal);
            break;
        }
        _2448 = fast::normalize(((in.v_tangent.xyz * _1169.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1169.y)) + (in.v_normal * _1169.z));
        break;
    } while(false);
    float3 _1369 = fast::clamp(_1155.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1378 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1177, 1.0 - _1177), fast::min(_1184, 1.0 - _1184)))), 0.0, 1.0);
    float _1457 = fast::max(dot(_2448, _1017), 9.9999997473787516355514526367188e-05);
    float4 _1525 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1457, params.facet_perceptualRoughness), level(0.0));
    float3 _1544 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1525.y) - 1.0));
    float3 _1619 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1622 = dot(_1619, _1619);
    float3 _1627 = _1619 * rsqrt(fast::max(_1622, 9.9999999392252902907785028219223e-09));
    float _1631 = _1622 * float(frame.punctualLights[0].positionFalloff.w);
    float _1636 = fast::clamp(fma(-_1631, _1631, 1.0), 0.0, 1.0);
    float _1655 = fast::clamp(fma(dot(-_1627, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1712 = fast::clamp(dot(_2448, _1627), 0.0, 1.0);
    float3 _1794 = fast::normalize(_1017 + _1627);
    float _1832 = 4096.0 * params.facet_alpha;
    float4 _1856 = float4(cross(_2448, _1794), params.facet_alpha * fast::clamp(dot(_2448, _1794), 0.0, 1.0)) * 64.0;
    float _1838 = _1832 / dot(_1856, _1856);
    float _1867 = params.facet_alpha * params.facet_alpha;
    float _1873 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1877 = sqrt(fma(_1457 * _1457, _1873, _1867));
    float _1900 = 1.0 - fast::clamp(dot(_1627, _1794), 0.0, 1.0);
    float _1903 = _1900 * _1900;
    float3 _1746 = _1369 * 0.3183098733425140380859375;
    float3 _1933 = fma(_1369 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2448.y)) + (frame.sh[2].xyz * _2448.z)) + (frame.sh[3].xyz * _2448.x)) + (((((frame.sh[4].xyz * (_2448.x * _2448.y)) + (frame.sh[5].xyz * (_2448.y * _2448.z))) + (frame.sh[6].xyz * fma(3.0 * _2448.z, _2448.z, -1.0))) + (frame.sh[7].xyz * (_2448.x * _2448.z))) + (frame.sh[8].xyz * fma(_2448.x, _2448.x, -(_2448.y * _2448.y)))), float3(0.0)), fast::max(float3(_1378), ((((((_1369 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1378) + ((_1369 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1378) + ((_1369 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1378), (facet_environment.sample(facet_environmentSmplr, reflect(-_1017, _2448), level(params.facet_environmentLod)).xyz * (mix(_1525.xxx, _1525.yyy, float3(0.039999999105930328369140625)) * _1544)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1457 + _1378)) - 1.0) + _1378, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1903 * _1903) * _1900))) * (((_1838 * _1838) * 0.3183098733425140380859375) * (0.5 / fma(_1712, _1877, _1457 * sqrt(fma(_1712 * _1712, _1873, _1867))))), _1544, _1746) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1636 * _1636) / fast::max(_1622, 9.9999997473787516355514526367188e-05)) * _1655) * _1655)) * _1712), float3(65504.0));
    float3 _1968 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1971 = dot(_1968, _1968);
    float3 _1976 = _1968 * rsqrt(fast::max(_1971, 9.9999999392252902907785028219223e-09));
    float _1980 = _1971 * float(frame.punctualLights[1].positionFalloff.w);
    float _1985 = fast::clamp(fma(-_1980, _1980, 1.0), 0.0, 1.0);
    float _2004 = fast::clamp(fma(dot(-_1976, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _2061 = fast::clamp(dot(_2448, _1976), 0.0, 1.0);
    float3 _2143 = fast::normalize(_1017 + _1976);
    float4 _2205 = float4(cross(_2448, _2143), params.facet_alpha * fast::clamp(dot(_2448, _2143), 0.0, 1.0)) * 64.0;
    float _2187 = _1832 / dot(_2205, _2205);
    float _2249 = 1.0 - fast::clamp(dot(_1976, _2143), 0.0, 1.0);
    float _2252 = _2249 * _2249;
    out.fragColor = float4(_1933 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2252 * _2252) * _2249))) * (((_2187 * _2187) * 0.3183098733425140380859375) * (0.5 / fma(_2061, _1877, _1457 * sqrt(fma(_2061 * _2061, _1873, _1867))))), _1544, _1746) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1985 * _1985) / fast::max(_1971, 9.9999997473787516355514526367188e-05)) * _2004) * _2004)) * _2061), float3(65504.0)), 1.0);
    return out;
}

