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
    float2 _1023 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1026 = facet_material_albedo.sample(facet_material_albedoSmplr, _1023);
    float4 _1036 = facet_material_relief.sample(facet_material_reliefSmplr, _1023);
    half3 _1040 = (half4(_1036).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2469;
    do
    {
        half3 _1053 = half4(in.v_tangent).xyz;
        if (float(dot(_1053, _1053)) == 0.0)
        {
            _2469 = normalize(half3(in.v_normal));
            break;
        }
        _2469 = normalize(((_1053 * _1040.x) + ((cross(half3(in.v_normal), _1053) * half(in.v_tangent.w)) * _1040.y)) + (half3(in.v_normal) * _1040.z));
        break;
    } while(false);
    half3 _1190 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2469.y)) + (half4(frame.sh[2]).xyz * _2469.z)) + (half4(frame.sh[3]).xyz * _2469.x)) + (((((half4(frame.sh[4]).xyz * (_2469.x * _2469.y)) + (half4(frame.sh[5]).xyz * (_2469.y * _2469.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2469.z, _2469.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2469.x * _2469.z))) + (half4(frame.sh[8]).xyz * fma(_2469.x, _2469.x, half(-float(_2469.y * _2469.y))))), half3(float3(0.0)));
    half3 _1213 = clamp(half4(_1026).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1248 = max(dot(_2469, half3(_875)), half(9.9999997473787516355514526367188e-05));
    float4 _1311 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1248, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1330 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1311).y) - half(1.0)));
    float4 _1337 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_875), _2469)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1477 = fast::normalize(_875 + frame.lightDirection.xyz);
    half _1397 = clamp(dot(_2469, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1517 = cross(_2469, half3(_1477));
    half _1520 = clamp(dot(_2469, half3(_1477)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1529 = half(params.facet_alpha) / fma(_1520, _1520, dot(_1517, _1517));
    half _1543 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1549 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1553 = sqrt(fma(_1248 * _1248, _1549, _1543));
    half _1577 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1477)), half(0.0), half(1.0));
    half _1580 = _1577 * _1577;
    half3 _1428 = _1213 * half(0.3183098733425140380859375);
    float3 _1646 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1649 = dot(_1646, _1646);
    float3 _1654 = _1646 * rsqrt(fast::max(_1649, 9.9999999392252902907785028219223e-09));
    float _1658 = _1649 * float(frame.punctualLights[0].positionFalloff.w);
    float _1663 = fast::clamp(fma(-_1658, _1658, 1.0), 0.0, 1.0);
    float _1682 = fast::clamp(fma(dot(-_1654, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1825 = fast::normalize(_875 + _1654);
    half _1745 = clamp(dot(_2469, half3(_1654)), half(0.0), half(1.0));
    half3 _1865 = cross(_2469, half3(_1825));
    half _1868 = clamp(dot(_2469, half3(_1825)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1877 = half(params.facet_alpha) / fma(_1868, _1868, dot(_1865, _1865));
    half _1925 = half(1.0) - clamp(dot(half3(_1654), half3(_1825)), half(0.0), half(1.0));
    half _1928 = _1925 * _1925;
    float3 _1994 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1997 = dot(_1994, _1994);
    float3 _2002 = _1994 * rsqrt(fast::max(_1997, 9.9999999392252902907785028219223e-09));
    float _2006 = _1997 * float(frame.punctualLights[1].positionFalloff.w);
    float _2011 = fast::clamp(fma(-_2006, _2006, 1.0), 0.0, 1.0);
    float _2030 = fast::clamp(fma(dot(-_2002, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2173 = fast::normalize(_875 + _2002);
    half _2093 = clamp(dot(_2469, half3(_2002)), half(0.0), half(1.0));
    half3 _2213 = cross(_2469, half3(_2173));
    half _2216 = clamp(dot(_2469, half3(_2173)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2225 = half(params.facet_alpha) / fma(_2216, _2216, dot(_2213, _2213));
    half _2273 = half(1.0) - clamp(dot(half3(_2002), half3(_2173)), half(0.0), half(1.0));
    half _2276 = _2273 * _2273;
    half3 _2306 = ((fma(_1213, _1190, half4(_1337).xyz * (mix(half4(_1311).xxx, half4(_1311).yyy, half3(float3(0.039999999105930328369140625))) * _1330)) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1580 * _1580) * _1577))) * min(min((_1529 * _1529) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1397, _1553, _1248 * sqrt(fma(_1397 * _1397, _1549, _1543))), half(65504.0)), half(65504.0)), _1330, _1428) * (half4(frame.lightColor).xyz * _1397), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1928 * _1928) * _1925))) * min(min((_1877 * _1877) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1745, _1553, _1248 * sqrt(fma(_1745 * _1745, _1549, _1543))), half(65504.0)), half(65504.0)), _1330, _1428) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1663) * half(_1663)) / fast::max(_1649, 9.9999997473787516355514526367188e-05)) * half(_1682)) * half(_1682)), float3(65504.0))) * _1745), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2276 * _2276) * _2273))) * min(min((_2225 * _2225) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2093, _1553, _1248 * sqrt(fma(_2093 * _2093, _1549, _1543))), half(65504.0)), half(65504.0)), _1330, _1428) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2011) * half(_2011)) / fast::max(_1997, 9.9999997473787516355514526367188e-05)) * half(_2030)) * half(_2030)), float3(65504.0))) * _2093), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2306, half(1.0)));
    return out;
}

