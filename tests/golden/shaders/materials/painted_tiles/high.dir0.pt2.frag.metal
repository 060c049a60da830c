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
    float3 _1040 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1175 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1178 = facet_material_albedo.sample(facet_material_albedoSmplr, _1175);
    float4 _1188 = facet_material_relief.sample(facet_material_reliefSmplr, _1175);
    half3 _1192 = (half4(_1188).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1198 = fract(_1175 * 4.0);
    float _1200 = _1198.x;
    float _1207 = _1198.y;
    half3 _2499;
    do
    {
        half3 _1232 = half4(in.v_tangent).xyz;
        if (float(dot(_1232, _1232)) == 0.0)
        {
            _2499 = normalize(half3(in.v_normal));
            break;
        }
        _2499 = normalize(((_1232 * _1192.x) + ((cross(half3(in.v_normal), _1232) * half(in.v_tangent.w)) * _1192.y)) + (half3(in.v_normal) * _1192.z));
        break;
    } while(false);
    half3 _1369 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2499.y)) + (half4(frame.sh[2]).xyz * _2499.z)) + (half4(frame.sh[3]).xyz * _2499.x)) + (((((half4(frame.sh[4]).xyz * (_2499.x * _2499.y)) + (half4(frame.sh[5]).xyz * (_2499.y * _2499.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2499.z, _2499.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2499.x * _2499.z))) + (half4(frame.sh[8]).xyz * fma(_2499.x, _2499.x, half(-float(_2499.y * _2499.y))))), half3(float3(0.0)));
    half3 _1392 = clamp(half4(_1178).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1401 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1200, 1.0 - _1200), fast::min(_1207, 1.0 - _1207))))), half(0.0), half(1.0));
    half _1482 = max(dot(_2499, half3(_1040)), half(9.9999997473787516355514526367188e-05));
    float4 _1547 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1482, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1566 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1547).y) - half(1.0)));
    float4 _1576 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1040), _2499)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1653 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1656 = dot(_1653, _1653);
    float3 _1661 = _1653 * rsqrt(fast::max(_1656, 9.9999999392252902907785028219223e-09));
    float _1665 = _1656 * float(frame.punctualLights[0].positionFalloff.w);
    float _1670 = fast::clamp(fma(-_1665, _1665, 1.0), 0.0, 1.0);
    float _1689 = fast::clamp(fma(dot(-_1661, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1832 = fast::normalize(_1040 + _1661);
    half _1752 = clamp(dot(_2499, half3(_1661)), half(0.0), half(1.0));
    half _1872 = half(4096.0) * half(params.facet_alpha);
    half4 _1897 = half4(cross(_2499, half3(_1832)), half(params.facet_alpha) * clamp(dot(_2499, half3(_1832)), half(0.0), half(1.0))) * half(64.0);
    half _1878 = _1872 / dot(_1897, _1897);
    half _1908 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1914 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1918 = sqrt(fma(_1482 * _1482, _1914, _1908));
    half _1942 = half(1.0) - clamp(dot(half3(_1661), half3(_1832)), half(0.0), half(1.0));
    half _1945 = _1942 * _1942;
    half3 _1783 = _1392 * half(0.3183098733425140380859375);
    float3 _2011 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2014 = dot(_2011, _2011);
    float3 _2019 = _2011 * rsqrt(fast::max(_2014, 9.9999999392252902907785028219223e-09));
    float _2023 = _2014 * float(frame.punctualLights[1].positionFalloff.w);
    float _2028 = fast::clamp(fma(-_2023, _2023, 1.0), 0.0, 1.0);
    float _2047 = fast::clamp(fma(dot(-_2019, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2190 = fast::normalize(_1040 + _2019);
    half _2110 = clamp(dot(_2499, half3(_2019)), half(0.0), half(1.0));
    half4 _2255 = half4(cross(_2499, half3(_2190)), half(params.facet_alpha) * clamp(dot(_2499, half3(_2190)), half(0.0), half(1.0))) * half(64.0);
    half _2236 = _1872 / dot(_2255, _2255);
    half _2300 = half(1.0) - clamp(dot(half3(_2019), half3(_2190)), half(0.0), half(1.0));
    half _2303 = _2300 * _2300;
    half3 _2333 = (fma(_1392 * _1369, max(half3(_1401), ((((((_1392 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1401) + ((_1392 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1401) + ((_1392 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1401), (half4(_1576).xyz * (mix(half4(_1547).xxx, half4(_1547).yyy, half3(float3(0.039999999105930328369140625))) * _1566)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1482 + _1401)) - half(1.0)) + _1401, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1945 * _1945) * _1942))) * min(min((_1878 * _1878) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1752, _1918, _1482 * sqrt(fma(_1752 * _1752, _1914, _1908))), half(65504.0)), half(65504.0)), _1566, _1783) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1670) * half(_1670)) / fast::max(_1656, 9.9999997473787516355514526367188e-05)) * half(_1689)) * half(_1689)), float3(65504.0))) * _1752), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2303 * _2303) * _2300))) * min(min((_2236 * _2236) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2110, _1918, _1482 * sqrt(fma(_2110 * _2110, _1914, _1908))), half(65504.0)), half(65504.0)), _1566, _1783) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2028) * half(_2028)) / fast::max(_2014, 9.9999997473787516355514526367188e-05)) * half(_2047)) * half(_2047)), float3(65504.0))) * _2110), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2333, half(1.0)));
    return out;
}

