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
    float3 _794 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _944 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _947 = facet_material_albedo.sample(facet_material_albedoSmplr, _944);
    float4 _957 = facet_material_relief.sample(facet_material_reliefSmplr, _944);
    half3 _961 = (half4(_957).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _967 = fract(_944 * 4.0);
    float _969 = _967.x;
    float _976 = _967.y;
    half3 _1951;
    do
    {
        half3 _1001 = half4(in.v_tangent).xyz;
        if (float(dot(_1001, _1001)) == 0.0)
        {
            _1951 = normalize(half3(in.v_normal));
            break;
        }
        _1951 = normalize(((_1001 * _961.x) + ((cross(half3(in.v_normal), _1001) * half(in.v_tangent.w)) * _961.y)) + (half3(in.v_normal) * _961.z));
        break;
    } while(false);
    half3 _1044 = clamp(half4(_947).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1053 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_969, 1.0 - _969), fast::min(_976, 1.0 - _976))))), half(0.0), half(1.0));
    half _1146 = max(dot(_1951, half3(_794)), half(9.9999997473787516355514526367188e-05));
    float4 _1211 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1146, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1230 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1211).y) - half(1.0)));
    float4 _1242 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_794), _1951)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1293 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1296 = dot(_1293, _1293);
    float3 _1301 = _1293 * rsqrt(fast::max(_1296, 9.9999999392252902907785028219223e-09));
    float _1305 = _1296 * float(frame.punctualLights[0].positionFalloff.w);
    float _1310 = fast::clamp(fma(-_1305, _1305, 1.0), 0.0, 1.0);
    float _1329 = fast::clamp(fma(dot(-_1301, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1463 = normalize(half3(_794) + half3(_1301));
    half _1390 = clamp(dot(_1951, half3(_1301)), half(0.0), half(1.0));
    half3 _1490 = cross(_1951, _1463);
    half _1493 = clamp(dot(_1951, _1463), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1510 = max(mix((half(2.0) * _1390) * _1146, _1390 + _1146, half(params.facet_alpha)), half(0.000244140625));
    half _1512 = half(1024.0) * half(params.facet_alpha);
    half _1517 = _1512 / (fma(_1493, _1493, dot(_1490, _1490)) * (half(6433.98193359375) * _1510));
    float3 _1565 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1568 = dot(_1565, _1565);
    float3 _1573 = _1565 * rsqrt(fast::max(_1568, 9.9999999392252902907785028219223e-09));
    float _1577 = _1568 * float(frame.punctualLights[1].positionFalloff.w);
    float _1582 = fast::clamp(fma(-_1577, _1577, 1.0), 0.0, 1.0);
    float _1601 = fast::clamp(fma(dot(-_1573, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1735 = normalize(half3(_794) + half3(_1573));
    half _1662 = clamp(dot(_1951, half3(_1573)), half(0.0), half(1.0));
    half3 _1762 = cross(_1951, _1735);
    half _1765 = clamp(dot(_1951, _1735), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1782 = max(mix((half(2.0) * _1662) * _1146, _1662 + _1146, half(params.facet_alpha)), half(0.000244140625));
    half _1789 = _1512 / (fma(_1765, _1765, dot(_1762, _1762)) * (half(6433.98193359375) * _1782));
    half3 _1801 = ((fma(_1044 * half3(in.v_diffuseLight), max(half3(_1053), ((((((_1044 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1053) + ((_1044 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1053) + ((_1044 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1053), _1044 * half3(in.v_directDiffuse)) + ((half4(_1242).xyz * (mix(half4(_1211).xxx, half4(_1211).yyy, half3(float3(0.039999999105930328369140625))) * _1230)) * _1053)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1517 * (_1517 * (half(6.283185482025146484375) * _1510)), half(65504.0))) * _1230) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1310) * half(_1310)) / fast::max(_1296, 9.9999997473787516355514526367188e-05)) * half(_1329)) * half(_1329)), float3(65504.0))) * _1390), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1789 * (_1789 * (half(6.283185482025146484375) * _1782)), half(65504.0))) * _1230) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1582) * half(_1582)) / fast::max(_1568, 9.9999997473787516355514526367188e-05)) * half(_1601)) * half(_1601)), float3(65504.0))) * _1662), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1801, half(1.0)));
    return out;
}

