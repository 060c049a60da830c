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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _614 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _764 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _768 = (half4(_764).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1628;
    do
    {
        half3 _781 = half4(in.v_tangent).xyz;
        if (float(dot(_781, _781)) == 0.0)
        {
            _1628 = normalize(half3(in.v_normal));
            break;
        }
        _1628 = normalize(((_781 * _768.x) + ((cross(half3(in.v_normal), _781) * half(in.v_tangent.w)) * _768.y)) + (half3(in.v_normal) * _768.z));
        break;
    } while(false);
    half3 _855 = reflect(-half3(_614), _1628);
    float4 _891 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1628, half3(_614)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _917 = facet_environment.sample(facet_environmentSmplr, float3(_855), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _870 = mix(half4(_891).xxx, half4(_891).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_891).y) - half(1.0))));
    half3 _655 = half4(frame.lightDirection).xyz;
    half _1046 = clamp(dot(_855, _655), half(0.0), half(1.0));
    half _1049 = _1046 * _1046;
    half4 _1681 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1049 * _1049, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1061 = _1681.x;
    float3 _1106 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1109 = dot(_1106, _1106);
    float3 _1114 = _1106 * rsqrt(fast::max(_1109, 9.9999999392252902907785028219223e-09));
    float _1118 = _1109 * float(frame.punctualLights[0].positionFalloff.w);
    float _1123 = fast::clamp(fma(-_1118, _1118, 1.0), 0.0, 1.0);
    float _1142 = fast::clamp(fma(dot(-_1114, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1274 = clamp(dot(_855, half3(_1114)), half(0.0), half(1.0));
    half _1277 = _1274 * _1274;
    half4 _1706 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1277 * _1277, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1289 = _1706.x;
    float3 _1334 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1337 = dot(_1334, _1334);
    float3 _1342 = _1334 * rsqrt(fast::max(_1337, 9.9999999392252902907785028219223e-09));
    float _1346 = _1337 * float(frame.punctualLights[1].positionFalloff.w);
    float _1351 = fast::clamp(fma(-_1346, _1346, 1.0), 0.0, 1.0);
    float _1370 = fast::clamp(fma(dot(-_1342, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1502 = clamp(dot(_855, half3(_1342)), half(0.0), half(1.0));
    half _1505 = _1502 * _1502;
    half4 _1732 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1505 * _1505, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1517 = _1732.x;
    half3 _1526 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_917).xyz * _870) + min((_870 * ((_1061 * _1061) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1628, _655), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_870 * ((_1289 * _1289) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1123) * half(_1123)) / fast::max(_1109, 9.9999997473787516355514526367188e-05)) * half(_1142)) * half(_1142)), float3(65504.0))) * clamp(dot(_1628, half3(_1114)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_870 * ((_1517 * _1517) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1351) * half(_1351)) / fast::max(_1337, 9.9999997473787516355514526367188e-05)) * half(_1370)) * half(_1370)), float3(65504.0))) * clamp(dot(_1628, half3(_1342)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1526, half(1.0)));
    return out;
}

