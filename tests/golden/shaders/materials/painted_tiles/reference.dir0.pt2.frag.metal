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
    float2 _1150 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1153 = facet_material_albedo.sample(facet_material_albedoSmplr, _1150);
    float4 _1163 = facet_material_relief.sample(facet_material_reliefSmplr, _1150);
    float3 _1167 = (_1163.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1173 = fract(_1150 * 4.0);
    float _1175 = _1173.x;
    float _1182 = _1173.y;
    float3 _2438;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2438 = fast::normalize(in.v_normal);
            break;
        }
        _2438 = fast::normalize(((in.v_tangent.xyz * _1167.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1167.y)) + (in.v_normal * _1167.z));
        break;
    } while(false);
    float3 _1367 = fast::clamp(_1153.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1376 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1175, 1.0 - _1175), fast::min(_1182, 1.0 - _1182)))), 0.0, 1.0);
    float _1457 = fast::max(dot(_2438, _1015), 9.9999997473787516355514526367188e-05);
    float4 _1522 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1457, params.facet_perceptualRoughness), level(0.0));
    float3 _1541 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1522.y) - 1.0));
    float3 _1629 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1632 = dot(_1629, _1629);
    float3 _1637 = _1629 * rsqrt(fast::max(_1632, 9.9999999392252902907785028219223e-09));
    float _1641 = _1632 * float(frame.punctualLights[0].positionFalloff.w);
    float _1646 = fast::clamp(fma(-_1641, _1641, 1.0), 0.0, 1.0);
    float _1665 = fast::clamp(fma(dot(-_1637, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1804 = fast::normalize(_1015 + _1637);
    float _1725 = fast::clamp(dot(_2438, _1637), 0.0, 1.0);
    float3 _1842 = cross(_2438, _1804);
    float _1845 = fast::clamp(dot(_2438, _1804), 0.0, 1.0) * params.facet_alpha;
    float _1854 = params.facet_alpha / fma(_1845, _1845, dot(_1842, _1842));
    float _1867 = params.facet_alpha * params.facet_alpha;
    float _1873 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1877 = sqrt(fma(_1457 * _1457, _1873, _1867));
    float _1900 = 1.0 - fast::clamp(dot(_1637, _1804), 0.0, 1.0);
    float _1903 = _1900 * _1900;
    float3 _1756 = _1367 * 0.3183098733425140380859375;
    float3 _1933 = fma(_1367 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2438.y)) + (frame.sh[2].xyz * _2438.z)) + (frame.sh[3].xyz * _2438.x)) + (((((frame.sh[4].xyz * (_2438.x * _2438.y)) + (frame.sh[5].xyz * (_2438.y * _2438.z))) + (frame.sh[6].xyz * fma(3.0 * _2438.z, _2438.z, -1.0))) + (frame.sh[7].xyz * (_2438.x * _2438.z))) + (frame.sh[8].xyz * fma(_2438.x, _2438.x, -(_2438.y * _2438.y)))), float3(0.0)), fast::max(float3(_1376), ((((((_1367 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1376) + ((_1367 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1376) + ((_1367 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1376), (facet_environment.sample(facet_environmentSmplr, reflect(-_1015, _2438), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1522.xxx, _1522.yyy, float3(0.039999999105930328369140625)) * _1541)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1457 + _1376)) - 1.0) + _1376, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1903 * _1903) * _1900))) * (((_1854 * _1854) * 0.3183098733425140380859375) * (0.5 / fma(_1725, _1877, _1457 * sqrt(fma(_1725 * _1725, _1873, _1867))))), _1541, _1756) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1646 * _1646) / fast::max(_1632, 9.9999997473787516355514526367188e-05)) * _1665) * _1665)) * _1725), float3(65504.0));
    float3 _1968 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1971 = dot(_1968, _1968);
    float3 _1976 = _1968 * rsqrt(fast::max(_1971, 9.9999999392252902907785028219223e-09));
    float _1980 = _1971 * float(frame.punctualLights[1].positionFalloff.w);
    float _1985 = fast::clamp(fma(-_1980, _1980, 1.0), 0.0, 1.0);
    float _2004 = fast::clamp(fma(dot(-_1976, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2143 = fast::normalize(_1015 + _1976);
    float _2064 = fast::clamp(dot(_2438, _1976), 0.0, 1.0);
    float3 _2181 = cross(_2438, _2143);
    float _2184 = fast::clamp(dot(_2438, _2143), 0.0, 1.0) * params.facet_alpha;
    float _2193 = params.facet_alpha / fma(_2184, _2184, dot(_2181, _2181));
    float _2239 = 1.0 - fast::clamp(dot(_1976, _2143), 0.0, 1.0);
    float _2242 = _2239 * _2239;
    out.fragColor = float4(_1933 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2242 * _2242) * _2239))) * (((_2193 * _2193) * 0.3183098733425140380859375) * (0.5 / fma(_2064, _1877, _1457 * sqrt(fma(_2064 * _2064, _1873, _1867))))), _1541, _1756) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1985 * _1985) / fast::max(_1971, 9.9999997473787516355514526367188e-05)) * _2004) * _2004)) * _2064), float3(65504.0)), 1.0);
    return out;
}

