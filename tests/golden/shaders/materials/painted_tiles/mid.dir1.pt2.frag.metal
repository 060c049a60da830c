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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _741 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _900 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _903 = facet_material_albedo.sample(facet_material_albedoSmplr, _900);
    float4 _913 = facet_material_relief.sample(facet_material_reliefSmplr, _900);
    half3 _917 = (half4(_913).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _923 = fract(_900 * 4.0);
    float _925 = _923.x;
    float _932 = _923.y;
    half3 _2027;
    do
    {
        half3 _957 = half4(in.v_tangent).xyz;
        if (float(dot(_957, _957)) == 0.0)
        {
            _2027 = normalize(half3(in.v_normal));
            break;
        }
        _2027 = normalize(((_957 * _917.x) + ((cross(half3(in.v_normal), _957) * half(in.v_tangent.w)) * _917.y)) + (half3(in.v_normal) * _917.z));
        break;
    } while(false);
    half _1006 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_925, 1.0 - _925), fast::min(_932, 1.0 - _932))))), half(0.0), half(1.0));
    half _1041 = max(dot(_2027, half3(_741)), half(9.9999997473787516355514526367188e-05));
    float4 _1106 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1041, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1125 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1106).y) - half(1.0)));
    float4 _1132 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_741), _2027)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _782 = half4(frame.lightDirection).xyz;
    half3 _1269 = normalize(half3(_741) + _782);
    half _1196 = clamp(dot(_2027, _782), half(0.0), half(1.0));
    half3 _1296 = cross(_2027, _1269);
    half _1299 = clamp(dot(_2027, _1269), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1316 = max(mix((half(2.0) * _1196) * _1041, _1196 + _1041, half(params.facet_alpha)), half(0.000244140625));
    half _1318 = half(1024.0) * half(params.facet_alpha);
    half _1323 = _1318 / (fma(_1299, _1299, dot(_1296, _1296)) * (half(6433.98193359375) * _1316));
    float3 _1371 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1374 = dot(_1371, _1371);
    float3 _1379 = _1371 * rsqrt(fast::max(_1374, 9.9999999392252902907785028219223e-09));
    float _1383 = _1374 * float(frame.punctualLights[0].positionFalloff.w);
    float _1388 = fast::clamp(fma(-_1383, _1383, 1.0), 0.0, 1.0);
    float _1407 = fast::clamp(fma(dot(-_1379, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1541 = normalize(half3(_741) + half3(_1379));
    half _1468 = clamp(dot(_2027, half3(_1379)), half(0.0), half(1.0));
    half3 _1568 = cross(_2027, _1541);
    half _1571 = clamp(dot(_2027, _1541), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1588 = max(mix((half(2.0) * _1468) * _1041, _1468 + _1041, half(params.facet_alpha)), half(0.000244140625));
    half _1595 = _1318 / (fma(_1571, _1571, dot(_1568, _1568)) * (half(6433.98193359375) * _1588));
    float3 _1643 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1646 = dot(_1643, _1643);
    float3 _1651 = _1643 * rsqrt(fast::max(_1646, 9.9999999392252902907785028219223e-09));
    float _1655 = _1646 * float(frame.punctualLights[1].positionFalloff.w);
    float _1660 = fast::clamp(fma(-_1655, _1655, 1.0), 0.0, 1.0);
    float _1679 = fast::clamp(fma(dot(-_1651, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1813 = normalize(half3(_741) + half3(_1651));
    half _1740 = clamp(dot(_2027, half3(_1651)), half(0.0), half(1.0));
    half3 _1840 = cross(_2027, _1813);
    half _1843 = clamp(dot(_2027, _1813), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1860 = max(mix((half(2.0) * _1740) * _1041, _1740 + _1041, half(params.facet_alpha)), half(0.000244140625));
    half _1867 = _1318 / (fma(_1843, _1843, dot(_1840, _1840)) * (half(6433.98193359375) * _1860));
    half3 _1879 = ((((((clamp(half4(_903).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0)) * half3(in.v_diffuseLight)) * _1006) + ((half4(_1132).xyz * (mix(half4(_1106).xxx, half4(_1106).yyy, half3(float3(0.039999999105930328369140625))) * _1125)) * _1006)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1323 * (_1323 * (half(6.283185482025146484375) * _1316)), half(65504.0))) * _1125) * (half4(frame.lightColor).xyz * _1196), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1595 * (_1595 * (half(6.283185482025146484375) * _1588)), half(65504.0))) * _1125) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1388) * half(_1388)) / fast::max(_1374, 9.9999997473787516355514526367188e-05)) * half(_1407)) * half(_1407)), float3(65504.0))) * _1468), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1867 * (_1867 * (half(6.283185482025146484375) * _1860)), half(65504.0))) * _1125) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1660) * half(_1660)) / fast::max(_1646, 9.9999997473787516355514526367188e-05)) * half(_1679)) * half(_1679)), float3(65504.0))) * _1740), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1879, half(1.0)));
    return out;
}

