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
    float2 _1020 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1023 = facet_material_albedo.sample(facet_material_albedoSmplr, _1020);
    float4 _1033 = facet_material_relief.sample(facet_material_reliefSmplr, _1020);
    half3 _1037 = (half4(_1033).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2466;
    do
    {
        half3 _1050 = half4(in.v_tangent).xyz;
        if (float(dot(_1050, _1050)) == 0.0)
        {
            _2466 = normalize(half3(in.v_normal));
            break;
        }
        _2466 = normalize(((_1050 * _1037.x) + ((cross(half3(in.v_normal), _1050) * half(in.v_tangent.w)) * _1037.y)) + (half3(in.v_normal) * _1037.z));
        break;
    } while(false);
    half3 _1187 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2466.y)) + (half4(frame.sh[2]).xyz * _2466.z)) + (half4(frame.sh[3]).xyz * _2466.x)) + (((((half4(frame.sh[4]).xyz * (_2466.x * _2466.y)) + (half4(frame.sh[5]).xyz * (_2466.y * _2466.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2466.z, _2466.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2466.x * _2466.z))) + (half4(frame.sh[8]).xyz * fma(_2466.x, _2466.x, half(-float(_2466.y * _2466.y))))), half3(float3(0.0)));
    half3 _1210 = clamp(half4(_1023).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1245 = max(dot(_2466, half3(_875)), half(9.9999997473787516355514526367188e-05));
    float4 _1308 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1245, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1327 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1308).y) - half(1.0)));
    float4 _1334 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_875), _2466)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1474 = fast::normalize(_875 + frame.lightDirection.xyz);
    half _1394 = clamp(dot(_2466, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1514 = cross(_2466, half3(_1474));
    half _1517 = clamp(dot(_2466, half3(_1474)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1526 = half(params.facet_alpha) / fma(_1517, _1517, dot(_1514, _1514));
    half _1540 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1546 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1550 = sqrt(fma(_1245 * _1245, _1546, _1540));
    half _1574 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1474)), half(0.0), half(1.0));
    half _1577 = _1574 * _1574;
    half3 _1425 = _1210 * half(0.3183098733425140380859375);
    float3 _1643 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1646 = dot(_1643, _1643);
    float3 _1651 = _1643 * rsqrt(fast::max(_1646, 9.9999999392252902907785028219223e-09));
    float _1655 = _1646 * float(frame.punctualLights[0].positionFalloff.w);
    float _1660 = fast::clamp(fma(-_1655, _1655, 1.0), 0.0, 1.0);
    float _1679 = fast::clamp(fma(dot(-_1651, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1822 = fast::normalize(_875 + _1651);
    half _1742 = clamp(dot(_2466, half3(_1651)), half(0.0), half(1.0));
    half3 _1862 = cross(_2466, half3(_1822));
    half _1865 = clamp(dot(_2466, half3(_1822)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1874 = half(params.facet_alpha) / fma(_1865, _1865, dot(_1862, _1862));
    half _1922 = half(1.0) - clamp(dot(half3(_1651), half3(_1822)), half(0.0), half(1.0));
    half _1925 = _1922 * _1922;
    float3 _1991 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1994 = dot(_1991, _1991);
    float3 _1999 = _1991 * rsqrt(fast::max(_1994, 9.9999999392252902907785028219223e-09));
    float _2003 = _1994 * float(frame.punctualLights[1].positionFalloff.w);
    float _2008 = fast::clamp(fma(-_2003, _2003, 1.0), 0.0, 1.0);
    float _2027 = fast::clamp(fma(dot(-_1999, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2170 = fast::normalize(_875 + _1999);
    half _2090 = clamp(dot(_2466, half3(_1999)), half(0.0), half(1.0));
    half3 _2210 = cross(_2466, half3(_2170));
    half _2213 = clamp(dot(_2466, half3(_2170)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2222 = half(params.facet_alpha) / fma(_2213, _2213, dot(_2210, _2210));
    half _2270 = half(1.0) - clamp(dot(half3(_1999), half3(_2170)), half(0.0), half(1.0));
    half _2273 = _2270 * _2270;
    half3 _2303 = ((fma(_1210, _1187, half4(_1334).xyz * (mix(half4(_1308).xxx, half4(_1308).yyy, half3(float3(0.039999999105930328369140625))) * _1327)) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1577 * _1577) * _1574))) * min(min((_1526 * _1526) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1394, _1550, _1245 * sqrt(fma(_1394 * _1394, _1546, _1540))), half(65504.0)), half(65504.0)), _1327, _1425) * (half4(frame.lightColor).xyz * _1394), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1925 * _1925) * _1922))) * min(min((_1874 * _1874) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1742, _1550, _1245 * sqrt(fma(_1742 * _1742, _1546, _1540))), half(65504.0)), half(65504.0)), _1327, _1425) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1660) * half(_1660)) / fast::max(_1646, 9.9999997473787516355514526367188e-05)) * half(_1679)) * half(_1679)), float3(65504.0))) * _1742), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2273 * _2273) * _2270))) * min(min((_2222 * _2222) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2090, _1550, _1245 * sqrt(fma(_2090 * _2090, _1546, _1540))), half(65504.0)), half(65504.0)), _1327, _1425) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2008) * half(_2008)) / fast::max(_1994, 9.9999997473787516355514526367188e-05)) * half(_2027)) * half(_2027)), float3(65504.0))) * _2090), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2303, half(1.0)));
    return out;
}

