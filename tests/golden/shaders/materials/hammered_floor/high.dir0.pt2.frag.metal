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
    float3 _898 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1028 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _1032 = (half4(_1028).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2191;
    do
    {
        half3 _1045 = half4(in.v_tangent).xyz;
        if (float(dot(_1045, _1045)) == 0.0)
        {
            _2191 = normalize(half3(in.v_normal));
            break;
        }
        _2191 = normalize(((_1045 * _1032.x) + ((cross(half3(in.v_normal), _1045) * half(in.v_tangent.w)) * _1032.y)) + (half3(in.v_normal) * _1032.z));
        break;
    } while(false);
    half _1081 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _1091 = dfdx(float3(_2191));
    float3 _1093 = dfdy(float3(_2191));
    half _1104 = _1081 * _1081;
    half3 _1222 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2191.y)) + (half4(frame.sh[2]).xyz * _2191.z)) + (half4(frame.sh[3]).xyz * _2191.x)) + (((((half4(frame.sh[4]).xyz * (_2191.x * _2191.y)) + (half4(frame.sh[5]).xyz * (_2191.y * _2191.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2191.z, _2191.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2191.x * _2191.z))) + (half4(frame.sh[8]).xyz * fma(_2191.x, _2191.x, half(-float(_2191.y * _2191.y))))), half3(float3(0.0)));
    half _1305 = clamp(half(sqrt(sqrt(fast::min(fma(float(_1104), float(_1104), fast::min((dot(_1091, _1091) + dot(_1093, _1093)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1272 = max(dot(_2191, half3(_898)), half(9.9999997473787516355514526367188e-05));
    float4 _1312 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1272, _1305)), level(0.0));
    half3 _1331 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1312).y) - half(1.0)));
    float4 _1341 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_898), _2191)), level(_1305 * (half(4.0) * (half(2.0) - _1305))));
    float3 _1386 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1389 = dot(_1386, _1386);
    float3 _1394 = _1386 * rsqrt(fast::max(_1389, 9.9999999392252902907785028219223e-09));
    float _1398 = _1389 * float(frame.punctualLights[0].positionFalloff.w);
    float _1403 = fast::clamp(fma(-_1398, _1398, 1.0), 0.0, 1.0);
    float _1422 = fast::clamp(fma(dot(-_1394, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1540 = _1305 * _1305;
    float3 _1552 = fast::normalize(_898 + _1394);
    half _1485 = clamp(dot(_2191, half3(_1394)), half(0.0), half(1.0));
    half _1592 = half(4096.0) * _1540;
    half4 _1617 = half4(cross(_2191, half3(_1552)), _1540 * clamp(dot(_2191, half3(_1552)), half(0.0), half(1.0))) * half(64.0);
    half _1598 = _1592 / dot(_1617, _1617);
    half _1628 = _1540 * _1540;
    half _1634 = fma(half(-float(_1540)), _1540, half(1.0));
    half _1638 = sqrt(fma(_1272 * _1272, _1634, _1628));
    half _1662 = half(1.0) - clamp(dot(half3(_1394), half3(_1552)), half(0.0), half(1.0));
    half _1665 = _1662 * _1662;
    half3 _1673 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1516 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1723 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1726 = dot(_1723, _1723);
    float3 _1731 = _1723 * rsqrt(fast::max(_1726, 9.9999999392252902907785028219223e-09));
    float _1735 = _1726 * float(frame.punctualLights[1].positionFalloff.w);
    float _1740 = fast::clamp(fma(-_1735, _1735, 1.0), 0.0, 1.0);
    float _1759 = fast::clamp(fma(dot(-_1731, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1889 = fast::normalize(_898 + _1731);
    half _1822 = clamp(dot(_2191, half3(_1731)), half(0.0), half(1.0));
    half4 _1954 = half4(cross(_2191, half3(_1889)), _1540 * clamp(dot(_2191, half3(_1889)), half(0.0), half(1.0))) * half(64.0);
    half _1935 = _1592 / dot(_1954, _1954);
    half _1999 = half(1.0) - clamp(dot(half3(_1731), half3(_1889)), half(0.0), half(1.0));
    half _2002 = _1999 * _1999;
    half3 _2024 = (fma(half3(float3(params.facet_diffuseColor)), _1222, half4(_1341).xyz * (mix(half4(_1312).xxx, half4(_1312).yyy, half3(float3(params.facet_f0))) * _1331)) + min(fma((half3(float3(params.facet_f0)) + (_1673 * ((_1665 * _1665) * _1662))) * min(min((_1598 * _1598) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1485, _1638, _1272 * sqrt(fma(_1485 * _1485, _1634, _1628))), half(65504.0)), half(65504.0)), _1331, _1516) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1403) * half(_1403)) / fast::max(_1389, 9.9999997473787516355514526367188e-05)) * half(_1422)) * half(_1422)), float3(65504.0))) * _1485), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1673 * ((_2002 * _2002) * _1999))) * min(min((_1935 * _1935) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1822, _1638, _1272 * sqrt(fma(_1822 * _1822, _1634, _1628))), half(65504.0)), half(65504.0)), _1331, _1516) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1740) * half(_1740)) / fast::max(_1726, 9.9999997473787516355514526367188e-05)) * half(_1759)) * half(_1759)), float3(65504.0))) * _1822), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2024, half(1.0)));
    return out;
}

