#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float tiling;
    float roughness;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _675 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _808 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _812 = (half4(_808).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1680;
    do
    {
        half3 _825 = half4(in.v_tangent).xyz;
        if (float(dot(_825, _825)) == 0.0)
        {
            _1680 = normalize(half3(in.v_normal));
            break;
        }
        _1680 = normalize(((_825 * _812.x) + ((cross(half3(in.v_normal), _825) * half(in.v_tangent.w)) * _812.y)) + (half3(in.v_normal) * _812.z));
        break;
    } while(false);
    half _861 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _871 = dfdx(float3(_1680));
    float3 _873 = dfdy(float3(_1680));
    half _884 = _861 * _861;
    half _960 = clamp(half(sqrt(sqrt(fast::min(fma(float(_884), float(_884), fast::min((dot(_871, _871) + dot(_873, _873)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _933 = max(dot(_1680, half3(_675)), half(9.9999997473787516355514526367188e-05));
    float4 _967 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_933, _960)), level(0.0));
    float4 _986 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_675), _1680)), level(_960 * (half(4.0) * (half(2.0) - _960))));
    float3 _1031 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1034 = dot(_1031, _1031);
    float3 _1039 = _1031 * rsqrt(fast::max(_1034, 9.9999999392252902907785028219223e-09));
    float _1043 = _1034 * float(frame.punctualLights[0].positionFalloff.w);
    float _1048 = fast::clamp(fma(-_1043, _1043, 1.0), 0.0, 1.0);
    float _1067 = fast::clamp(fma(dot(-_1039, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1174 = _960 * _960;
    half _1125 = clamp(dot(_1680, half3(_1039)), half(0.0), half(1.0));
    half3 _1185 = normalize(half3(_675) + half3(_1039));
    half4 _1254 = half4(cross(_1680, _1185), _1174 * clamp(dot(_1680, _1185), half(0.0), half(1.0))) * half(64.0);
    half _1228 = half(4096.0) * _1174;
    half _1231 = half(6.283185482025146484375) * max(mix((half(2.0) * _1125) * _933, _1125 + _933, _1174), half(0.000244140625));
    half _1233 = _1228 / (dot(_1254, _1254) * _1231);
    float3 _1298 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1301 = dot(_1298, _1298);
    float3 _1306 = _1298 * rsqrt(fast::max(_1301, 9.9999999392252902907785028219223e-09));
    float _1310 = _1301 * float(frame.punctualLights[1].positionFalloff.w);
    float _1315 = fast::clamp(fma(-_1310, _1310, 1.0), 0.0, 1.0);
    float _1334 = fast::clamp(fma(dot(-_1306, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1392 = clamp(dot(_1680, half3(_1306)), half(0.0), half(1.0));
    half3 _1452 = normalize(half3(_675) + half3(_1306));
    half4 _1521 = half4(cross(_1680, _1452), _1174 * clamp(dot(_1680, _1452), half(0.0), half(1.0))) * half(64.0);
    half _1498 = half(6.283185482025146484375) * max(mix((half(2.0) * _1392) * _933, _1392 + _933, _1174), half(0.000244140625));
    half _1500 = _1228 / (dot(_1521, _1521) * _1498);
    half3 _1529 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_986).xyz * mix(half4(_967).xxx, half4(_967).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min(_1233 * (_1233 * _1231), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1048) * half(_1048)) / fast::max(_1034, 9.9999997473787516355514526367188e-05)) * half(_1067)) * half(_1067)), float3(65504.0))) * _1125), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min(_1500 * (_1500 * _1498), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1315) * half(_1315)) / fast::max(_1301, 9.9999997473787516355514526367188e-05)) * half(_1334)) * half(_1334)), float3(65504.0))) * _1392), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1529, half(1.0)));
    return out;
}

