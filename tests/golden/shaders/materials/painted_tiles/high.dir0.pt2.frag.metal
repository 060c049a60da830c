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
    float3 _1022 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1157 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1160 = facet_material_albedo.sample(facet_material_albedoSmplr, _1157);
    float4 _1170 = facet_material_relief.sample(facet_material_reliefSmplr, _1157);
    half3 _1174 = (half4(_1170).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1180 = fract(_1157 * 4.0);
    float _1182 = _1180.x;
    float _1189 = _1180.y;
    half3 _2461;
    do
    {
        half3 _1214 = half4(in.v_tangent).xyz;
        if (float(dot(_1214, _1214)) == 0.0)
        {
            _2461 = normalize(half3(in.v_normal));
            break;
        }
        _2461 = normalize(((_1214 * _1174.x) + ((cross(half3(in.v_normal), _1214) * half(in.v_tangent.w)) * _1174.y)) + (half3(in.v_normal) * _1174.z));
        break;
    } while(false);
    half3 _1351 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2461.y)) + (half4(frame.sh[2]).xyz * _2461.z)) + (half4(frame.sh[3]).xyz * _2461.x)) + (((((half4(frame.sh[4]).xyz * (_2461.x * _2461.y)) + (half4(frame.sh[5]).xyz * (_2461.y * _2461.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2461.z, _2461.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2461.x * _2461.z))) + (half4(frame.sh[8]).xyz * fma(_2461.x, _2461.x, half(-float(_2461.y * _2461.y))))), half3(float3(0.0)));
    half3 _1374 = clamp(half4(_1160).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1383 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1182, 1.0 - _1182), fast::min(_1189, 1.0 - _1189))))), half(0.0), half(1.0));
    half _1464 = max(dot(_2461, half3(_1022)), half(9.9999997473787516355514526367188e-05));
    float4 _1529 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1464, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1548 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1529).y) - half(1.0)));
    float4 _1558 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1022), _2461)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1635 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1638 = dot(_1635, _1635);
    float3 _1643 = _1635 * rsqrt(fast::max(_1638, 9.9999999392252902907785028219223e-09));
    float _1647 = _1638 * float(frame.punctualLights[0].positionFalloff.w);
    float _1652 = fast::clamp(fma(-_1647, _1647, 1.0), 0.0, 1.0);
    float _1671 = fast::clamp(fma(dot(-_1643, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1814 = fast::normalize(_1022 + _1643);
    half _1734 = clamp(dot(_2461, half3(_1643)), half(0.0), half(1.0));
    half3 _1854 = cross(_2461, half3(_1814));
    half _1857 = clamp(dot(_2461, half3(_1814)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1866 = half(params.facet_alpha) / fma(_1857, _1857, dot(_1854, _1854));
    half _1880 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1886 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1890 = sqrt(fma(_1464 * _1464, _1886, _1880));
    half _1914 = half(1.0) - clamp(dot(half3(_1643), half3(_1814)), half(0.0), half(1.0));
    half _1917 = _1914 * _1914;
    half3 _1765 = _1374 * half(0.3183098733425140380859375);
    float3 _1983 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1986 = dot(_1983, _1983);
    float3 _1991 = _1983 * rsqrt(fast::max(_1986, 9.9999999392252902907785028219223e-09));
    float _1995 = _1986 * float(frame.punctualLights[1].positionFalloff.w);
    float _2000 = fast::clamp(fma(-_1995, _1995, 1.0), 0.0, 1.0);
    float _2019 = fast::clamp(fma(dot(-_1991, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2162 = fast::normalize(_1022 + _1991);
    half _2082 = clamp(dot(_2461, half3(_1991)), half(0.0), half(1.0));
    half3 _2202 = cross(_2461, half3(_2162));
    half _2205 = clamp(dot(_2461, half3(_2162)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _2214 = half(params.facet_alpha) / fma(_2205, _2205, dot(_2202, _2202));
    half _2262 = half(1.0) - clamp(dot(half3(_1991), half3(_2162)), half(0.0), half(1.0));
    half _2265 = _2262 * _2262;
    half3 _2295 = (fma(_1374 * _1351, max(half3(_1383), ((((((_1374 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1383) + ((_1374 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1383) + ((_1374 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1383), (half4(_1558).xyz * (mix(half4(_1529).xxx, half4(_1529).yyy, half3(float3(0.039999999105930328369140625))) * _1548)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1464 + _1383)) - half(1.0)) + _1383, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1917 * _1917) * _1914))) * min(min((_1866 * _1866) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1734, _1890, _1464 * sqrt(fma(_1734 * _1734, _1886, _1880))), half(65504.0)), half(65504.0)), _1548, _1765) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1652) * half(_1652)) / fast::max(_1638, 9.9999997473787516355514526367188e-05)) * half(_1671)) * half(_1671)), float3(65504.0))) * _1734), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2265 * _2265) * _2262))) * min(min((_2214 * _2214) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2082, _1890, _1464 * sqrt(fma(_2082 * _2082, _1886, _1880))), half(65504.0)), half(65504.0)), _1548, _1765) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2000) * half(_2000)) / fast::max(_1986, 9.9999997473787516355514526367188e-05)) * half(_2019)) * half(_2019)), float3(65504.0))) * _2082), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2295, half(1.0)));
    return out;
}

