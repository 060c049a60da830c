#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float tiling;
    float roughness;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_relief [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_reliefSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _875 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1026 = facet_material_relief.sample(facet_material_reliefSmplr, (in.v_uv0 * params.tiling));
    half3 _1030 = (half4(_1026).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2409;
    do
    {
        half3 _1043 = half4(in.v_tangent).xyz;
        if (float(dot(_1043, _1043)) == 0.0)
        {
            _2409 = normalize(half3(in.v_normal));
            break;
        }
        _2409 = normalize(((_1043 * _1030.x) + ((cross(half3(in.v_normal), _1043) * half(in.v_tangent.w)) * _1030.y)) + (half3(in.v_normal) * _1030.z));
        break;
    } while(false);
    half _1079 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _1088 = dfdx(float3(_2409));
    float3 _1090 = dfdy(float3(_2409));
    half _1101 = _1079 * _1079;
    half3 _1218 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2409.y)) + (half4(frame.sh[2]).xyz * _2409.z)) + (half4(frame.sh[3]).xyz * _2409.x)) + (((((half4(frame.sh[4]).xyz * (_2409.x * _2409.y)) + (half4(frame.sh[5]).xyz * (_2409.y * _2409.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2409.z, _2409.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2409.x * _2409.z))) + (half4(frame.sh[8]).xyz * fma(_2409.x, _2409.x, half(-float(_2409.y * _2409.y))))), half3(float3(0.0)));
    half _1301 = clamp(sqrt(sqrt(min(fma(_1101, _1101, min((dot(half3(_1088), half3(_1088)) + dot(half3(_1090), half3(_1090))) * half(0.300000011920928955078125), half(0.20000000298023223876953125))), half(1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1268 = max(dot(_2409, half3(_875)), half(9.9999997473787516355514526367188e-05));
    float4 _1308 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1268, _1301)), level(0.0));
    half3 _1327 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1308).y) - half(1.0)));
    float4 _1334 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_875), _2409)), level(_1301 * half(4.0)));
    half _1449 = _1301 * _1301;
    float3 _1461 = fast::normalize(_875 + frame.lightDirection.xyz);
    half _1394 = clamp(dot(_2409, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1501 = cross(_2409, half3(_1461));
    half _1504 = clamp(dot(_2409, half3(_1461)), half(0.0), half(1.0)) * _1449;
    half _1513 = _1449 / fma(_1504, _1504, dot(_1501, _1501));
    half _1527 = _1449 * _1449;
    half _1533 = fma(half(-float(_1449)), _1449, half(1.0));
    half _1537 = sqrt(fma(_1268 * _1268, _1533, _1527));
    half _1561 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1461)), half(0.0), half(1.0));
    half _1564 = _1561 * _1561;
    half3 _1572 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1425 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1622 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1625 = dot(_1622, _1622);
    float3 _1630 = _1622 * rsqrt(fast::max(_1625, 9.9999999392252902907785028219223e-09));
    float _1634 = _1625 * float(frame.punctualLights[0].positionFalloff.w);
    float _1639 = fast::clamp(fma(-_1634, _1634, 1.0), 0.0, 1.0);
    float _1658 = fast::clamp(fma(dot(-_1630, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1788 = fast::normalize(_875 + _1630);
    half _1721 = clamp(dot(_2409, half3(_1630)), half(0.0), half(1.0));
    half3 _1828 = cross(_2409, half3(_1788));
    half _1831 = clamp(dot(_2409, half3(_1788)), half(0.0), half(1.0)) * _1449;
    half _1840 = _1449 / fma(_1831, _1831, dot(_1828, _1828));
    half _1888 = half(1.0) - clamp(dot(half3(_1630), half3(_1788)), half(0.0), half(1.0));
    half _1891 = _1888 * _1888;
    half3 _1913 = (fma(half3(float3(params.facet_diffuseColor)), _1218, half4(_1334).xyz * (mix(half4(_1308).xxx, half4(_1308).yyy, half3(float3(params.facet_f0))) * _1327)) + min(fma((half3(float3(params.facet_f0)) + (_1572 * ((_1564 * _1564) * _1561))) * min(min((_1513 * _1513) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1394, _1537, _1268 * sqrt(fma(_1394 * _1394, _1533, _1527))), half(65504.0)), half(65504.0)), _1327, _1425) * (half4(frame.lightColor).xyz * _1394), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1572 * ((_1891 * _1891) * _1888))) * min(min((_1840 * _1840) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1721, _1537, _1268 * sqrt(fma(_1721 * _1721, _1533, _1527))), half(65504.0)), half(65504.0)), _1327, _1425) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1639) * half(_1639)) / fast::max(_1625, 9.9999997473787516355514526367188e-05)) * half(_1658)) * half(_1658)), float3(65504.0))) * _1721), half3(float3(65504.0)));
    float3 _1949 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1952 = dot(_1949, _1949);
    float3 _1957 = _1949 * rsqrt(fast::max(_1952, 9.9999999392252902907785028219223e-09));
    float _1961 = _1952 * float(frame.punctualLights[1].positionFalloff.w);
    float _1966 = fast::clamp(fma(-_1961, _1961, 1.0), 0.0, 1.0);
    float _1985 = fast::clamp(fma(dot(-_1957, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2115 = fast::normalize(_875 + _1957);
    half _2048 = clamp(dot(_2409, half3(_1957)), half(0.0), half(1.0));
    half3 _2155 = cross(_2409, half3(_2115));
    half _2158 = clamp(dot(_2409, half3(_2115)), half(0.0), half(1.0)) * _1449;
    half _2167 = _1449 / fma(_2158, _2158, dot(_2155, _2155));
    half _2215 = half(1.0) - clamp(dot(half3(_1957), half3(_2115)), half(0.0), half(1.0));
    half _2218 = _2215 * _2215;
    half3 _2240 = _1913 + min(fma((half3(float3(params.facet_f0)) + (_1572 * ((_2218 * _2218) * _2215))) * min(min((_2167 * _2167) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2048, _1537, _1268 * sqrt(fma(_2048 * _2048, _1533, _1527))), half(65504.0)), half(65504.0)), _1327, _1425) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1966) * half(_1966)) / fast::max(_1952, 9.9999997473787516355514526367188e-05)) * half(_1985)) * half(_1985)), float3(65504.0))) * _2048), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2240, half(1.0)));
    return out;
}

