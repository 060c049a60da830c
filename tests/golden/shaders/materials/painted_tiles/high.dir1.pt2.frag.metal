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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _861 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1017 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _1020 = facet_material_albedo.sample(facet_material_albedoSmplr, _1017);
    float4 _1030 = facet_material_relief.sample(facet_material_reliefSmplr, _1017);
    half3 _1034 = (half4(_1030).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _1040 = fract(_1017 * 4.0);
    float _1042 = _1040.x;
    float _1049 = _1040.y;
    half3 _2396;
    do
    {
        half3 _1074 = half4(in.v_tangent).xyz;
        if (float(dot(_1074, _1074)) == 0.0)
        {
            _2396 = normalize(half3(in.v_normal));
            break;
        }
        _2396 = normalize(((_1074 * _1034.x) + ((cross(half3(in.v_normal), _1074) * half(in.v_tangent.w)) * _1034.y)) + (half3(in.v_normal) * _1034.z));
        break;
    } while(false);
    float4 _1110 = facet_irradiance.sample(facet_irradianceSmplr, float3(_2396), level(0.0));
    half3 _1134 = clamp(half4(_1020).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1143 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1042, 1.0 - _1042), fast::min(_1049, 1.0 - _1049))))), half(0.0), half(1.0));
    half _1222 = max(dot(_2396, half3(_861)), half(9.9999997473787516355514526367188e-05));
    float4 _1281 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1222, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1300 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_861), _2396)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1443 = fast::normalize(_861 + frame.lightDirection.xyz);
    half _1366 = clamp(dot(_2396, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1483 = half(4096.0) * half(params.facet_alpha);
    half4 _1508 = half4(cross(_2396, half3(_1443)), half(params.facet_alpha) * clamp(dot(_2396, half3(_1443)), half(0.0), half(1.0))) * half(64.0);
    half _1489 = _1483 / dot(_1508, _1508);
    half _1533 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1443)), half(0.0), half(1.0));
    half _1536 = _1533 * _1533;
    half3 _1394 = _1134 * half(0.3183098733425140380859375);
    float3 _1602 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1605 = dot(_1602, _1602);
    float3 _1610 = _1602 * rsqrt(fast::max(_1605, 9.9999999392252902907785028219223e-09));
    float _1614 = _1605 * float(frame.punctualLights[0].positionFalloff.w);
    float _1619 = fast::clamp(fma(-_1614, _1614, 1.0), 0.0, 1.0);
    float _1638 = fast::clamp(fma(dot(-_1610, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1778 = fast::normalize(_861 + _1610);
    half _1701 = clamp(dot(_2396, half3(_1610)), half(0.0), half(1.0));
    half4 _1843 = half4(cross(_2396, half3(_1778)), half(params.facet_alpha) * clamp(dot(_2396, half3(_1778)), half(0.0), half(1.0))) * half(64.0);
    half _1824 = _1483 / dot(_1843, _1843);
    half _1868 = half(1.0) - clamp(dot(half3(_1610), half3(_1778)), half(0.0), half(1.0));
    half _1871 = _1868 * _1868;
    half3 _1901 = (fma(_1134 * half4(_1110).xyz, max(half3(_1143), ((((((_1134 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1143) + ((_1134 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1143) + ((_1134 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1143), (half4(_1300).xyz * mix(half4(_1281).xxx, half4(_1281).yyy, half3(float3(0.039999999105930328369140625)))) * _1143) + min((_1394 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1536 * _1536) * _1533))) * min(min((_1489 * _1489) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1366) * _1222, _1366 + _1222, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _1366), half3(float3(65504.0)))) + min((_1394 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_1871 * _1871) * _1868))) * min(min((_1824 * _1824) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1701) * _1222, _1701 + _1222, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1619) * half(_1619)) / fast::max(_1605, 9.9999997473787516355514526367188e-05)) * half(_1638)) * half(_1638)), float3(65504.0))) * _1701), half3(float3(65504.0)));
    float3 _1937 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1940 = dot(_1937, _1937);
    float3 _1945 = _1937 * rsqrt(fast::max(_1940, 9.9999999392252902907785028219223e-09));
    float _1949 = _1940 * float(frame.punctualLights[1].positionFalloff.w);
    float _1954 = fast::clamp(fma(-_1949, _1949, 1.0), 0.0, 1.0);
    float _1973 = fast::clamp(fma(dot(-_1945, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2113 = fast::normalize(_861 + _1945);
    half _2036 = clamp(dot(_2396, half3(_1945)), half(0.0), half(1.0));
    half4 _2178 = half4(cross(_2396, half3(_2113)), half(params.facet_alpha) * clamp(dot(_2396, half3(_2113)), half(0.0), half(1.0))) * half(64.0);
    half _2159 = _1483 / dot(_2178, _2178);
    half _2203 = half(1.0) - clamp(dot(half3(_1945), half3(_2113)), half(0.0), half(1.0));
    half _2206 = _2203 * _2203;
    float4 _2568 = float4(half4(_1901 + min((_1394 + ((half3(float3(0.039999999105930328369140625)) + (half3(float3(0.959999978542327880859375)) * ((_2206 * _2206) * _2203))) * min(min((_2159 * _2159) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _2036) * _1222, _2036 + _1222, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1954) * half(_1954)) / fast::max(_1940, 9.9999997473787516355514526367188e-05)) * half(_1973)) * half(_1973)), float3(65504.0))) * _2036), half3(float3(65504.0))), half(1.0)));
    out.fragColor = _2568;
    return out;
}

