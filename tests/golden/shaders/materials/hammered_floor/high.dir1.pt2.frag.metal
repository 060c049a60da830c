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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _877 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1028 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _1032 = (half4(_1028).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2413;
    do
    {
        half3 _1045 = half4(in.v_tangent).xyz;
        if (float(dot(_1045, _1045)) == 0.0)
        {
            _2413 = normalize(half3(in.v_normal));
            break;
        }
        _2413 = normalize(((_1045 * _1032.x) + ((cross(half3(in.v_normal), _1045) * half(in.v_tangent.w)) * _1032.y)) + (half3(in.v_normal) * _1032.z));
        break;
    } while(false);
    half _1081 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _1091 = dfdx(float3(_2413));
    float3 _1093 = dfdy(float3(_2413));
    half _1104 = _1081 * _1081;
    half3 _1222 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2413.y)) + (half4(frame.sh[2]).xyz * _2413.z)) + (half4(frame.sh[3]).xyz * _2413.x)) + (((((half4(frame.sh[4]).xyz * (_2413.x * _2413.y)) + (half4(frame.sh[5]).xyz * (_2413.y * _2413.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2413.z, _2413.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2413.x * _2413.z))) + (half4(frame.sh[8]).xyz * fma(_2413.x, _2413.x, half(-float(_2413.y * _2413.y))))), half3(float3(0.0)));
    half _1305 = clamp(half(sqrt(sqrt(fast::min(fma(float(_1104), float(_1104), fast::min((dot(_1091, _1091) + dot(_1093, _1093)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1272 = max(dot(_2413, half3(_877)), half(9.9999997473787516355514526367188e-05));
    float4 _1312 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1272, _1305)), level(0.0));
    half3 _1331 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1312).y) - half(1.0)));
    float4 _1338 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_877), _2413)), level(_1305 * half(4.0)));
    half _1453 = _1305 * _1305;
    float3 _1465 = fast::normalize(_877 + frame.lightDirection.xyz);
    half _1398 = clamp(dot(_2413, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1505 = cross(_2413, half3(_1465));
    half _1508 = clamp(dot(_2413, half3(_1465)), half(0.0), half(1.0)) * _1453;
    half _1517 = _1453 / fma(_1508, _1508, dot(_1505, _1505));
    half _1531 = _1453 * _1453;
    half _1537 = fma(half(-float(_1453)), _1453, half(1.0));
    half _1541 = sqrt(fma(_1272 * _1272, _1537, _1531));
    half _1565 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1465)), half(0.0), half(1.0));
    half _1568 = _1565 * _1565;
    half3 _1576 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1429 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1626 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1629 = dot(_1626, _1626);
    float3 _1634 = _1626 * rsqrt(fast::max(_1629, 9.9999999392252902907785028219223e-09));
    float _1638 = _1629 * float(frame.punctualLights[0].positionFalloff.w);
    float _1643 = fast::clamp(fma(-_1638, _1638, 1.0), 0.0, 1.0);
    float _1662 = fast::clamp(fma(dot(-_1634, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1792 = fast::normalize(_877 + _1634);
    half _1725 = clamp(dot(_2413, half3(_1634)), half(0.0), half(1.0));
    half3 _1832 = cross(_2413, half3(_1792));
    half _1835 = clamp(dot(_2413, half3(_1792)), half(0.0), half(1.0)) * _1453;
    half _1844 = _1453 / fma(_1835, _1835, dot(_1832, _1832));
    half _1892 = half(1.0) - clamp(dot(half3(_1634), half3(_1792)), half(0.0), half(1.0));
    half _1895 = _1892 * _1892;
    half3 _1917 = (fma(half3(float3(params.facet_diffuseColor)), _1222, half4(_1338).xyz * (mix(half4(_1312).xxx, half4(_1312).yyy, half3(float3(params.facet_f0))) * _1331)) + min(fma((half3(float3(params.facet_f0)) + (_1576 * ((_1568 * _1568) * _1565))) * min(min((_1517 * _1517) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1398, _1541, _1272 * sqrt(fma(_1398 * _1398, _1537, _1531))), half(65504.0)), half(65504.0)), _1331, _1429) * (half4(frame.lightColor).xyz * _1398), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1576 * ((_1895 * _1895) * _1892))) * min(min((_1844 * _1844) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1725, _1541, _1272 * sqrt(fma(_1725 * _1725, _1537, _1531))), half(65504.0)), half(65504.0)), _1331, _1429) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1643) * half(_1643)) / fast::max(_1629, 9.9999997473787516355514526367188e-05)) * half(_1662)) * half(_1662)), float3(65504.0))) * _1725), half3(float3(65504.0)));
    float3 _1953 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1956 = dot(_1953, _1953);
    float3 _1961 = _1953 * rsqrt(fast::max(_1956, 9.9999999392252902907785028219223e-09));
    float _1965 = _1956 * float(frame.punctualLights[1].positionFalloff.w);
    float _1970 = fast::clamp(fma(-_1965, _1965, 1.0), 0.0, 1.0);
    float _1989 = fast::clamp(fma(dot(-_1961, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2119 = fast::normalize(_877 + _1961);
    half _2052 = clamp(dot(_2413, half3(_1961)), half(0.0), half(1.0));
    half3 _2159 = cross(_2413, half3(_2119));
    half _2162 = clamp(dot(_2413, half3(_2119)), half(0.0), half(1.0)) * _1453;
    half _2171 = _1453 / fma(_2162, _2162, dot(_2159, _2159));
    half _2219 = half(1.0) - clamp(dot(half3(_1961), half3(_2119)), half(0.0), half(1.0));
    half _2222 = _2219 * _2219;
    half3 _2244 = _1917 + min(fma((half3(float3(params.facet_f0)) + (_1576 * ((_2222 * _2222) * _2219))) * min(min((_2171 * _2171) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2052, _1541, _1272 * sqrt(fma(_2052 * _2052, _1537, _1531))), half(65504.0)), half(65504.0)), _1331, _1429) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1970) * half(_1970)) / fast::max(_1956, 9.9999997473787516355514526367188e-05)) * half(_1989)) * half(_1989)), float3(65504.0))) * _2052), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2244, half(1.0)));
    return out;
}

