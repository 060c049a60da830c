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
    float3 _1037 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1193 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1196 = facet_material_albedo.sample(facet_material_albedoSmplr, _1193);
    float4 _1206 = facet_material_relief.sample(facet_material_reliefSmplr, _1193);
    half3 _1210 = (half4(_1206).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1216 = fract(_1193 * 4.0);
    float _1218 = _1216.x;
    float _1225 = _1216.y;
    half3 _2798;
    do
    {
        half3 _1250 = half4(in.v_tangent).xyz;
        if (float(dot(_1250, _1250)) == 0.0)
        {
            _2798 = normalize(half3(in.v_normal));
            break;
        }
        _2798 = normalize(((_1250 * _1210.x) + ((cross(half3(in.v_normal), _1250) * half(in.v_tangent.w)) * _1210.y)) + (half3(in.v_normal) * _1210.z));
        break;
    } while(false);
    half3 _1387 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2798.y)) + (half4(frame.sh[2]).xyz * _2798.z)) + (half4(frame.sh[3]).xyz * _2798.x)) + (((((half4(frame.sh[4]).xyz * (_2798.x * _2798.y)) + (half4(frame.sh[5]).xyz * (_2798.y * _2798.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2798.z, _2798.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2798.x * _2798.z))) + (half4(frame.sh[8]).xyz * fma(_2798.x, _2798.x, half(-float(_2798.y * _2798.y))))), half3(float3(0.0)));
    half3 _1410 = clamp(half4(_1196).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1419 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1218, 1.0 - _1218), fast::min(_1225, 1.0 - _1225))))), half(0.0), half(1.0));
    half _1500 = max(dot(_2798, half3(_1037)), half(9.9999997473787516355514526367188e-05));
    float4 _1565 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1500, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1584 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1565).y) - half(1.0)));
    float4 _1591 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_1037), _2798)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1763 = fast::normalize(_1037 + frame.lightDirection.xyz);
    half _1683 = clamp(dot(_2798, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1803 = half(4096.0) * half(params.facet_alpha);
    half4 _1828 = half4(cross(_2798, half3(_1763)), half(params.facet_alpha) * clamp(dot(_2798, half3(_1763)), half(0.0), half(1.0))) * half(64.0);
    half _1809 = _1803 / dot(_1828, _1828);
    half _1839 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1845 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1849 = sqrt(fma(_1500 * _1500, _1845, _1839));
    half _1873 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1763)), half(0.0), half(1.0));
    half _1876 = _1873 * _1873;
    half3 _1714 = _1410 * half(0.3183098733425140380859375);
    float3 _1942 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1945 = dot(_1942, _1942);
    float3 _1950 = _1942 * rsqrt(fast::max(_1945, 9.9999999392252902907785028219223e-09));
    float _1954 = _1945 * float(frame.punctualLights[0].positionFalloff.w);
    float _1959 = fast::clamp(fma(-_1954, _1954, 1.0), 0.0, 1.0);
    float _1978 = fast::clamp(fma(dot(-_1950, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2121 = fast::normalize(_1037 + _1950);
    half _2041 = clamp(dot(_2798, half3(_1950)), half(0.0), half(1.0));
    half4 _2186 = half4(cross(_2798, half3(_2121)), half(params.facet_alpha) * clamp(dot(_2798, half3(_2121)), half(0.0), half(1.0))) * half(64.0);
    half _2167 = _1803 / dot(_2186, _2186);
    half _2231 = half(1.0) - clamp(dot(half3(_1950), half3(_2121)), half(0.0), half(1.0));
    half _2234 = _2231 * _2231;
    half3 _2264 = (fma(_1410 * _1387, max(half3(_1419), ((((((_1410 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1419) + ((_1410 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1419) + ((_1410 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1419), (half4(_1591).xyz * (mix(half4(_1565).xxx, half4(_1565).yyy, half3(float3(0.039999999105930328369140625))) * _1584)) * clamp((exp2(exp2(fma(half(-16.0), half(params.facet_perceptualRoughness) * half(params.facet_perceptualRoughness), half(-1.0))) * log2(_1500 + _1419)) - half(1.0)) + _1419, half(0.0), half(1.0))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1876 * _1876) * _1873))) * min(min((_1809 * _1809) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1683, _1849, _1500 * sqrt(fma(_1683 * _1683, _1845, _1839))), half(65504.0)), half(65504.0)), _1584, _1714) * (half4(frame.lightColor).xyz * _1683), half3(float3(65504.0)))) + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2234 * _2234) * _2231))) * min(min((_2167 * _2167) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2041, _1849, _1500 * sqrt(fma(_2041 * _2041, _1845, _1839))), half(65504.0)), half(65504.0)), _1584, _1714) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1959) * half(_1959)) / fast::max(_1945, 9.9999997473787516355514526367188e-05)) * half(_1978)) * half(_1978)), float3(65504.0))) * _2041), half3(float3(65504.0)));
    float3 _2300 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2303 = dot(_2300, _2300);
    float3 _2308 = _2300 * rsqrt(fast::max(_2303, 9.9999999392252902907785028219223e-09));
    float _2312 = _2303 * float(frame.punctualLights[1].positionFalloff.w);
    float _2317 = fast::clamp(fma(-_2312, _2312, 1.0), 0.0, 1.0);
    float _2336 = fast::clamp(fma(dot(-_2308, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2479 = fast::normalize(_1037 + _2308);
    half _2399 = clamp(dot(_2798, half3(_2308)), half(0.0), half(1.0));
    half4 _2544 = half4(cross(_2798, half3(_2479)), half(params.facet_alpha) * clamp(dot(_2798, half3(_2479)), half(0.0), half(1.0))) * half(64.0);
    half _2525 = _1803 / dot(_2544, _2544);
    half _2589 = half(1.0) - clamp(dot(half3(_2308), half3(_2479)), half(0.0), half(1.0));
    half _2592 = _2589 * _2589;
    half4 _2637 = half4(_2264 + min(fma((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2592 * _2592) * _2589))) * min(min((_2525 * _2525) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2399, _1849, _1500 * sqrt(fma(_2399 * _2399, _1845, _1839))), half(65504.0)), half(65504.0)), _1584, _1714) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2317) * half(_2317)) / fast::max(_2303, 9.9999997473787516355514526367188e-05)) * half(_2336)) * half(_2336)), float3(65504.0))) * _2399), half3(float3(65504.0))), half(1.0));
    out.fragColor = float4(_2637);
    return out;
}

