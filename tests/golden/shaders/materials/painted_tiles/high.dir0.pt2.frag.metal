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
    float3 _875 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1002 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1005 = facet_material_albedo.sample(facet_material_albedoSmplr, _1002);
    float4 _1015 = facet_material_relief.sample(facet_material_reliefSmplr, _1002);
    half3 _1019 = (half4(_1015).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2174;
    do
    {
        half3 _1032 = half4(in.v_tangent).xyz;
        if (float(dot(_1032, _1032)) == 0.0)
        {
            _2174 = normalize(half3(in.v_normal));
            break;
        }
        _2174 = normalize(((_1032 * _1019.x) + ((cross(half3(in.v_normal), _1032) * half(in.v_tangent.w)) * _1019.y)) + (half3(in.v_normal) * _1019.z));
        break;
    } while(false);
    half3 _1169 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2174.y)) + (half4(frame.sh[2]).xyz * _2174.z)) + (half4(frame.sh[3]).xyz * _2174.x)) + (((((half4(frame.sh[4]).xyz * (_2174.x * _2174.y)) + (half4(frame.sh[5]).xyz * (_2174.y * _2174.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2174.z, _2174.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2174.x * _2174.z))) + (half4(frame.sh[8]).xyz * fma(_2174.x, _2174.x, half(-float(_2174.y * _2174.y))))), half3(float3(0.0)));
    half3 _1192 = clamp(half4(_1005).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1227 = max(dot(_2174, half3(_875)), half(9.9999997473787516355514526367188e-05));
    float4 _1290 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1227, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1309 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1290).y) - half(1.0)));
    float4 _1316 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_875), _2174)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1361 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1364 = dot(_1361, _1361);
    float3 _1369 = _1361 * rsqrt(fast::max(_1364, 9.9999999392252902907785028219223e-09));
    float _1373 = _1364 * float(frame.punctualLights[0].positionFalloff.w);
    float _1378 = fast::clamp(fma(-_1373, _1373, 1.0), 0.0, 1.0);
    float _1397 = fast::clamp(fma(dot(-_1369, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1540 = fast::normalize(_875 + _1369);
    half _1460 = clamp(dot(_2174, half3(_1369)), half(0.0), half(1.0));
    half3 _1580 = cross(_2174, half3(_1540));
    half _1583 = clamp(dot(_2174, half3(_1540)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1592 = half(params.facet_alpha) / fma(_1583, _1583, dot(_1580, _1580));
    half _1606 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1612 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1616 = sqrt(fma(_1227 * _1227, _1612, _1606));
    half _1640 = half(1.0) - clamp(dot(half3(_1369), half3(_1540)), half(0.0), half(1.0));
    half _1643 = _1640 * _1640;
    half3 _1491 = _1192 * half(0.3183098733425140380859375);
    float3 _1709 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1712 = dot(_1709, _1709);
    float3 _1717 = _1709 * rsqrt(fast::max(_1712, 9.9999999392252902907785028219223e-09));
    float _1721 = _1712 * float(frame.punctualLights[1].positionFalloff.w);
    float _1726 = fast::clamp(fma(-_1721, _1721, 1.0), 0.0, 1.0);
    float _1745 = fast::clamp(fma(dot(-_1717, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1888 = fast::normalize(_875 + _1717);
    half _1808 = clamp(dot(_2174, half3(_1717)), half(0.0), half(1.0));
    half3 _1928 = cross(_2174, half3(_1888));
    half _1931 = clamp(dot(_2174, half3(_1888)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1940 = half(params.facet_alpha) / fma(_1931, _1931, dot(_1928, _1928));
    half _1988 = half(1.0) - clamp(dot(half3(_1717), half3(_1888)), half(0.0), half(1.0));
    half _1991 = _1988 * _1988;
    half3 _2021 = (fma(_1192, _1169, half4(_1316).xyz * (mix(half4(_1290).xxx, half4(_1290).yyy, half3(float3(0.039999999105930328369140625))) * _1309)) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1643 * _1643) * _1640))) * min(min((_1592 * _1592) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1460, _1616, _1227 * sqrt(fma(_1460 * _1460, _1612, _1606))), half(65504.0)), half(65504.0)), _1309, _1491) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1378) * half(_1378)) / fast::max(_1364, 9.9999997473787516355514526367188e-05)) * half(_1397)) * half(_1397)), float3(65504.0))) * _1460), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1991 * _1991) * _1988))) * min(min((_1940 * _1940) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1808, _1616, _1227 * sqrt(fma(_1808 * _1808, _1612, _1606))), half(65504.0)), half(65504.0)), _1309, _1491) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1726) * half(_1726)) / fast::max(_1712, 9.9999997473787516355514526367188e-05)) * half(_1745)) * half(_1745)), float3(65504.0))) * _1808), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2021, half(1.0)));
    return out;
}

