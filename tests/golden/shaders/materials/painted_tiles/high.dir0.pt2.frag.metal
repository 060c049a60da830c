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
    float2 _999 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1002 = facet_material_albedo.sample(facet_material_albedoSmplr, _999);
    float4 _1012 = facet_material_relief.sample(facet_material_reliefSmplr, _999);
    half3 _1016 = (half4(_1012).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2171;
    do
    {
        half3 _1029 = half4(in.v_tangent).xyz;
        if (float(dot(_1029, _1029)) == 0.0)
        {
            _2171 = normalize(half3(in.v_normal));
            break;
        }
        _2171 = normalize(((_1029 * _1016.x) + ((cross(half3(in.v_normal), _1029) * half(in.v_tangent.w)) * _1016.y)) + (half3(in.v_normal) * _1016.z));
        break;
    } while(false);
    half3 _1166 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2171.y)) + (half4(frame.sh[2]).xyz * _2171.z)) + (half4(frame.sh[3]).xyz * _2171.x)) + (((((half4(frame.sh[4]).xyz * (_2171.x * _2171.y)) + (half4(frame.sh[5]).xyz * (_2171.y * _2171.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2171.z, _2171.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2171.x * _2171.z))) + (half4(frame.sh[8]).xyz * fma(_2171.x, _2171.x, half(-float(_2171.y * _2171.y))))), half3(float3(0.0)));
    half3 _1189 = clamp(half4(_1002).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1224 = max(dot(_2171, half3(_875)), half(9.9999997473787516355514526367188e-05));
    float4 _1287 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1224, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1306 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1287).y) - half(1.0)));
    float4 _1313 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_875), _2171)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1358 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1361 = dot(_1358, _1358);
    float3 _1366 = _1358 * rsqrt(fast::max(_1361, 9.9999999392252902907785028219223e-09));
    float _1370 = _1361 * float(frame.punctualLights[0].positionFalloff.w);
    float _1375 = fast::clamp(fma(-_1370, _1370, 1.0), 0.0, 1.0);
    float _1394 = fast::clamp(fma(dot(-_1366, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1537 = fast::normalize(_875 + _1366);
    half _1457 = clamp(dot(_2171, half3(_1366)), half(0.0), half(1.0));
    half3 _1577 = cross(_2171, half3(_1537));
    half _1580 = clamp(dot(_2171, half3(_1537)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1589 = half(params.facet_alpha) / fma(_1580, _1580, dot(_1577, _1577));
    half _1603 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1609 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1613 = sqrt(fma(_1224 * _1224, _1609, _1603));
    half _1637 = half(1.0) - clamp(dot(half3(_1366), half3(_1537)), half(0.0), half(1.0));
    half _1640 = _1637 * _1637;
    half3 _1488 = _1189 * half(0.3183098733425140380859375);
    float3 _1706 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1709 = dot(_1706, _1706);
    float3 _1714 = _1706 * rsqrt(fast::max(_1709, 9.9999999392252902907785028219223e-09));
    float _1718 = _1709 * float(frame.punctualLights[1].positionFalloff.w);
    float _1723 = fast::clamp(fma(-_1718, _1718, 1.0), 0.0, 1.0);
    float _1742 = fast::clamp(fma(dot(-_1714, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1885 = fast::normalize(_875 + _1714);
    half _1805 = clamp(dot(_2171, half3(_1714)), half(0.0), half(1.0));
    half3 _1925 = cross(_2171, half3(_1885));
    half _1928 = clamp(dot(_2171, half3(_1885)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1937 = half(params.facet_alpha) / fma(_1928, _1928, dot(_1925, _1925));
    half _1985 = half(1.0) - clamp(dot(half3(_1714), half3(_1885)), half(0.0), half(1.0));
    half _1988 = _1985 * _1985;
    half3 _2018 = (fma(_1189, _1166, half4(_1313).xyz * (mix(half4(_1287).xxx, half4(_1287).yyy, half3(float3(0.039999999105930328369140625))) * _1306)) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1640 * _1640) * _1637))) * min(min((_1589 * _1589) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1457, _1613, _1224 * sqrt(fma(_1457 * _1457, _1609, _1603))), half(65504.0)), half(65504.0)), _1306, _1488) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1375) * half(_1375)) / fast::max(_1361, 9.9999997473787516355514526367188e-05)) * half(_1394)) * half(_1394)), float3(65504.0))) * _1457), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1988 * _1988) * _1985))) * min(min((_1937 * _1937) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1805, _1613, _1224 * sqrt(fma(_1805 * _1805, _1609, _1603))), half(65504.0)), half(65504.0)), _1306, _1488) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1723) * half(_1723)) / fast::max(_1709, 9.9999997473787516355514526367188e-05)) * half(_1742)) * half(_1742)), float3(65504.0))) * _1805), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2018, half(1.0)));
    return out;
}

