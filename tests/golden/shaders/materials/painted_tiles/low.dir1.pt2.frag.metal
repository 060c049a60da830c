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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _724 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _898 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _901 = facet_material_albedo.sample(facet_material_albedoSmplr, _898);
    float4 _911 = facet_material_relief.sample(facet_material_reliefSmplr, _898);
    half3 _915 = (half4(_911).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _921 = fract(_898 * 4.0);
    float _923 = _921.x;
    float _930 = _921.y;
    half3 _1964;
    do
    {
        half3 _955 = half4(in.v_tangent).xyz;
        if (float(dot(_955, _955)) == 0.0)
        {
            _1964 = normalize(half3(in.v_normal));
            break;
        }
        _1964 = normalize(((_955 * _915.x) + ((cross(half3(in.v_normal), _955) * half(in.v_tangent.w)) * _915.y)) + (half3(in.v_normal) * _915.z));
        break;
    } while(false);
    half3 _998 = clamp(half4(_901).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1004 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_923, 1.0 - _923), fast::min(_930, 1.0 - _930))))), half(0.0), half(1.0));
    half3 _1055 = reflect(-half3(_724), _1964);
    float4 _1117 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1964, half3(_724)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1143 = facet_environment.sample(facet_environmentSmplr, float3(_1055), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1070 = mix(half4(_1117).xxx, half4(_1117).yyy, half3(float3(0.039999999105930328369140625))) * (half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1117).y) - half(1.0))));
    half3 _777 = half4(frame.lightDirection).xyz;
    half _1302 = clamp(dot(_1055, _777), half(0.0), half(1.0));
    half _1305 = _1302 * _1302;
    half4 _2033 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1305 * _1305, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1317 = _2033.x;
    float3 _1362 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1365 = dot(_1362, _1362);
    float3 _1370 = _1362 * rsqrt(fast::max(_1365, 9.9999999392252902907785028219223e-09));
    float _1374 = _1365 * float(frame.punctualLights[0].positionFalloff.w);
    float _1379 = fast::clamp(fma(-_1374, _1374, 1.0), 0.0, 1.0);
    float _1398 = fast::clamp(fma(dot(-_1370, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1554 = clamp(dot(_1055, half3(_1370)), half(0.0), half(1.0));
    half _1557 = _1554 * _1554;
    half4 _2058 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1557 * _1557, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1569 = _2058.x;
    float3 _1614 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1617 = dot(_1614, _1614);
    float3 _1622 = _1614 * rsqrt(fast::max(_1617, 9.9999999392252902907785028219223e-09));
    float _1626 = _1617 * float(frame.punctualLights[1].positionFalloff.w);
    float _1631 = fast::clamp(fma(-_1626, _1626, 1.0), 0.0, 1.0);
    float _1650 = fast::clamp(fma(dot(-_1622, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1806 = clamp(dot(_1055, half3(_1622)), half(0.0), half(1.0));
    half _1809 = _1806 * _1806;
    half4 _2084 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1809 * _1809, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1821 = _2084.x;
    half3 _1830 = (((fma(_998, half3(in.v_directDiffuse), (_998 * half3(in.v_diffuseLight)) * _1004) + ((half4(_1143).xyz * _1070) * _1004)) + min((_1070 * ((_1317 * _1317) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1964, _777), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1070 * ((_1569 * _1569) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1379) * half(_1379)) / fast::max(_1365, 9.9999997473787516355514526367188e-05)) * half(_1398)) * half(_1398)), float3(65504.0))) * clamp(dot(_1964, half3(_1370)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1070 * ((_1821 * _1821) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1631) * half(_1631)) / fast::max(_1617, 9.9999997473787516355514526367188e-05)) * half(_1650)) * half(_1650)), float3(65504.0))) * clamp(dot(_1964, half3(_1622)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1830, half(1.0)));
    return out;
}

