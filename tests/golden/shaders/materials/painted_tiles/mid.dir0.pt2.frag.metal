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
    float3 _807 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _957 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _960 = facet_material_albedo.sample(facet_material_albedoSmplr, _957);
    float4 _970 = facet_material_relief.sample(facet_material_reliefSmplr, _957);
    half3 _974 = (half4(_970).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _980 = fract(_957 * 4.0);
    float _982 = _980.x;
    float _989 = _980.y;
    half3 _1981;
    do
    {
        half3 _1014 = half4(in.v_tangent).xyz;
        if (float(dot(_1014, _1014)) == 0.0)
        {
            _1981 = normalize(half3(in.v_normal));
            break;
        }
        _1981 = normalize(((_1014 * _974.x) + ((cross(half3(in.v_normal), _1014) * half(in.v_tangent.w)) * _974.y)) + (half3(in.v_normal) * _974.z));
        break;
    } while(false);
    half3 _1057 = clamp(half4(_960).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1066 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_982, 1.0 - _982), fast::min(_989, 1.0 - _989))))), half(0.0), half(1.0));
    half _1159 = max(dot(_1981, half3(_807)), half(9.9999997473787516355514526367188e-05));
    float4 _1224 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1159, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1243 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1224).y) - half(1.0)));
    float4 _1250 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_807), _1981)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1301 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1304 = dot(_1301, _1301);
    float3 _1309 = _1301 * rsqrt(fast::max(_1304, 9.9999999392252902907785028219223e-09));
    float _1313 = _1304 * float(frame.punctualLights[0].positionFalloff.w);
    float _1318 = fast::clamp(fma(-_1313, _1313, 1.0), 0.0, 1.0);
    float _1337 = fast::clamp(fma(dot(-_1309, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1471 = normalize(half3(_807) + half3(_1309));
    half _1398 = clamp(dot(_1981, half3(_1309)), half(0.0), half(1.0));
    half4 _1540 = half4(cross(_1981, _1471), half(params.facet_alpha) * clamp(dot(_1981, _1471), half(0.0), half(1.0))) * half(64.0);
    half _1514 = half(4096.0) * half(params.facet_alpha);
    half _1517 = half(6.283185482025146484375) * max(mix((half(2.0) * _1398) * _1159, _1398 + _1159, half(params.facet_alpha)), half(0.000244140625));
    half _1519 = _1514 / (dot(_1540, _1540) * _1517);
    float3 _1584 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1587 = dot(_1584, _1584);
    float3 _1592 = _1584 * rsqrt(fast::max(_1587, 9.9999999392252902907785028219223e-09));
    float _1596 = _1587 * float(frame.punctualLights[1].positionFalloff.w);
    float _1601 = fast::clamp(fma(-_1596, _1596, 1.0), 0.0, 1.0);
    float _1620 = fast::clamp(fma(dot(-_1592, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1754 = normalize(half3(_807) + half3(_1592));
    half _1681 = clamp(dot(_1981, half3(_1592)), half(0.0), half(1.0));
    half4 _1823 = half4(cross(_1981, _1754), half(params.facet_alpha) * clamp(dot(_1981, _1754), half(0.0), half(1.0))) * half(64.0);
    half _1800 = half(6.283185482025146484375) * max(mix((half(2.0) * _1681) * _1159, _1681 + _1159, half(params.facet_alpha)), half(0.000244140625));
    half _1802 = _1514 / (dot(_1823, _1823) * _1800);
    half3 _1831 = ((fma(_1057 * half3(in.v_diffuseLight), max(half3(_1066), ((((((_1057 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1066) + ((_1057 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1066) + ((_1057 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1066), _1057 * half3(in.v_directDiffuse)) + ((half4(_1250).xyz * (mix(half4(_1224).xxx, half4(_1224).yyy, half3(float3(0.039999999105930328369140625))) * _1243)) * _1066)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1519 * (_1519 * _1517), half(65504.0))) * _1243) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1318) * half(_1318)) / fast::max(_1304, 9.9999997473787516355514526367188e-05)) * half(_1337)) * half(_1337)), float3(65504.0))) * _1398), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1802 * (_1802 * _1800), half(65504.0))) * _1243) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1601) * half(_1601)) / fast::max(_1587, 9.9999997473787516355514526367188e-05)) * half(_1620)) * half(_1620)), float3(65504.0))) * _1681), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1831, half(1.0)));
    return out;
}

