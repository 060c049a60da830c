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
    float3 v_diffuseLight [[user(locn4)]];
    float3 v_directDiffuse [[user(locn5)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _792 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _942 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _945 = facet_material_albedo.sample(facet_material_albedoSmplr, _942);
    float4 _955 = facet_material_relief.sample(facet_material_reliefSmplr, _942);
    half3 _959 = (half4(_955).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _965 = fract(_942 * 4.0);
    float _967 = _965.x;
    float _974 = _965.y;
    half3 _1947;
    do
    {
        half3 _999 = half4(in.v_tangent).xyz;
        if (float(dot(_999, _999)) == 0.0)
        {
            _1947 = normalize(half3(in.v_normal));
            break;
        }
        _1947 = normalize(((_999 * _959.x) + ((cross(half3(in.v_normal), _999) * half(in.v_tangent.w)) * _959.y)) + (half3(in.v_normal) * _959.z));
        break;
    } while(false);
    half3 _1042 = clamp(half4(_945).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1051 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_967, 1.0 - _967), fast::min(_974, 1.0 - _974))))), half(0.0), half(1.0));
    half _1144 = max(dot(_1947, half3(_792)), half(9.9999997473787516355514526367188e-05));
    float4 _1209 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1144, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1228 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1209).y) - half(1.0)));
    float4 _1238 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_792), _1947)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1289 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1292 = dot(_1289, _1289);
    float3 _1297 = _1289 * rsqrt(fast::max(_1292, 9.9999999392252902907785028219223e-09));
    float _1301 = _1292 * float(frame.punctualLights[0].positionFalloff.w);
    float _1306 = fast::clamp(fma(-_1301, _1301, 1.0), 0.0, 1.0);
    float _1325 = fast::clamp(fma(dot(-_1297, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1459 = normalize(half3(_792) + half3(_1297));
    half _1386 = clamp(dot(_1947, half3(_1297)), half(0.0), half(1.0));
    half3 _1486 = cross(_1947, _1459);
    half _1489 = clamp(dot(_1947, _1459), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1506 = max(mix((half(2.0) * _1386) * _1144, _1386 + _1144, half(params.facet_alpha)), half(0.000244140625));
    half _1508 = half(1024.0) * half(params.facet_alpha);
    half _1513 = _1508 / (fma(_1489, _1489, dot(_1486, _1486)) * (half(6433.98193359375) * _1506));
    float3 _1561 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1564 = dot(_1561, _1561);
    float3 _1569 = _1561 * rsqrt(fast::max(_1564, 9.9999999392252902907785028219223e-09));
    float _1573 = _1564 * float(frame.punctualLights[1].positionFalloff.w);
    float _1578 = fast::clamp(fma(-_1573, _1573, 1.0), 0.0, 1.0);
    float _1597 = fast::clamp(fma(dot(-_1569, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1731 = normalize(half3(_792) + half3(_1569));
    half _1658 = clamp(dot(_1947, half3(_1569)), half(0.0), half(1.0));
    half3 _1758 = cross(_1947, _1731);
    half _1761 = clamp(dot(_1947, _1731), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1778 = max(mix((half(2.0) * _1658) * _1144, _1658 + _1144, half(params.facet_alpha)), half(0.000244140625));
    half _1785 = _1508 / (fma(_1761, _1761, dot(_1758, _1758)) * (half(6433.98193359375) * _1778));
    half3 _1797 = ((fma(_1042 * half3(in.v_diffuseLight), max(half3(_1051), ((((((_1042 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1051) + ((_1042 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1051) + ((_1042 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1051), _1042 * half3(in.v_directDiffuse)) + ((half4(_1238).xyz * (mix(half4(_1209).xxx, half4(_1209).yyy, half3(float3(0.039999999105930328369140625))) * _1228)) * _1051)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1513 * (_1513 * (half(6.283185482025146484375) * _1506)), half(65504.0))) * _1228) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1306) * half(_1306)) / fast::max(_1292, 9.9999997473787516355514526367188e-05)) * half(_1325)) * half(_1325)), float3(65504.0))) * _1386), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1785 * (_1785 * (half(6.283185482025146484375) * _1778)), half(65504.0))) * _1228) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1578) * half(_1578)) / fast::max(_1564, 9.9999997473787516355514526367188e-05)) * half(_1597)) * half(_1597)), float3(65504.0))) * _1658), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1797, half(1.0)));
    return out;
}

