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
    float3 _789 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _939 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _942 = facet_material_albedo.sample(facet_material_albedoSmplr, _939);
    float4 _952 = facet_material_relief.sample(facet_material_reliefSmplr, _939);
    half3 _956 = (half4(_952).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _962 = fract(_939 * 4.0);
    float _964 = _962.x;
    float _971 = _962.y;
    half3 _1941;
    do
    {
        half3 _996 = half4(in.v_tangent).xyz;
        if (float(dot(_996, _996)) == 0.0)
        {
            _1941 = normalize(half3(in.v_normal));
            break;
        }
        _1941 = normalize(((_996 * _956.x) + ((cross(half3(in.v_normal), _996) * half(in.v_tangent.w)) * _956.y)) + (half3(in.v_normal) * _956.z));
        break;
    } while(false);
    half3 _1039 = clamp(half4(_942).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1048 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_964, 1.0 - _964), fast::min(_971, 1.0 - _971))))), half(0.0), half(1.0));
    half _1141 = max(dot(_1941, half3(_789)), half(9.9999997473787516355514526367188e-05));
    float4 _1206 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1141, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1225 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1206).y) - half(1.0)));
    float4 _1232 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_789), _1941)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1283 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1286 = dot(_1283, _1283);
    float3 _1291 = _1283 * rsqrt(fast::max(_1286, 9.9999999392252902907785028219223e-09));
    float _1295 = _1286 * float(frame.punctualLights[0].positionFalloff.w);
    float _1300 = fast::clamp(fma(-_1295, _1295, 1.0), 0.0, 1.0);
    float _1319 = fast::clamp(fma(dot(-_1291, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1453 = normalize(half3(_789) + half3(_1291));
    half _1380 = clamp(dot(_1941, half3(_1291)), half(0.0), half(1.0));
    half3 _1480 = cross(_1941, _1453);
    half _1483 = clamp(dot(_1941, _1453), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1500 = max(mix((half(2.0) * _1380) * _1141, _1380 + _1141, half(params.facet_alpha)), half(0.000244140625));
    half _1502 = half(1024.0) * half(params.facet_alpha);
    half _1507 = _1502 / (fma(_1483, _1483, dot(_1480, _1480)) * (half(6433.98193359375) * _1500));
    float3 _1555 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1558 = dot(_1555, _1555);
    float3 _1563 = _1555 * rsqrt(fast::max(_1558, 9.9999999392252902907785028219223e-09));
    float _1567 = _1558 * float(frame.punctualLights[1].positionFalloff.w);
    float _1572 = fast::clamp(fma(-_1567, _1567, 1.0), 0.0, 1.0);
    float _1591 = fast::clamp(fma(dot(-_1563, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1725 = normalize(half3(_789) + half3(_1563));
    half _1652 = clamp(dot(_1941, half3(_1563)), half(0.0), half(1.0));
    half3 _1752 = cross(_1941, _1725);
    half _1755 = clamp(dot(_1941, _1725), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1772 = max(mix((half(2.0) * _1652) * _1141, _1652 + _1141, half(params.facet_alpha)), half(0.000244140625));
    half _1779 = _1502 / (fma(_1755, _1755, dot(_1752, _1752)) * (half(6433.98193359375) * _1772));
    half3 _1791 = ((fma(_1039 * half3(in.v_diffuseLight), max(half3(_1048), ((((((_1039 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1048) + ((_1039 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1048) + ((_1039 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1048), _1039 * half3(in.v_directDiffuse)) + ((half4(_1232).xyz * (mix(half4(_1206).xxx, half4(_1206).yyy, half3(float3(0.039999999105930328369140625))) * _1225)) * _1048)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1507 * (_1507 * (half(6.283185482025146484375) * _1500)), half(65504.0))) * _1225) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1300) * half(_1300)) / fast::max(_1286, 9.9999997473787516355514526367188e-05)) * half(_1319)) * half(_1319)), float3(65504.0))) * _1380), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1779 * (_1779 * (half(6.283185482025146484375) * _1772)), half(65504.0))) * _1225) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1572) * half(_1572)) / fast::max(_1558, 9.9999997473787516355514526367188e-05)) * half(_1591)) * half(_1591)), float3(65504.0))) * _1652), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1791, half(1.0)));
    return out;
}

