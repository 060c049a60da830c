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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _643 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _800 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _804 = (half4(_800).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1774;
    do
    {
        half3 _817 = half4(in.v_tangent).xyz;
        if (float(dot(_817, _817)) == 0.0)
        {
            _1774 = normalize(half3(in.v_normal));
            break;
        }
        _1774 = normalize(((_817 * _804.x) + ((cross(half3(in.v_normal), _817) * half(in.v_tangent.w)) * _804.y)) + (half3(in.v_normal) * _804.z));
        break;
    } while(false);
    half _853 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _863 = dfdx(float3(_1774));
    float3 _865 = dfdy(float3(_1774));
    half _876 = _853 * _853;
    half _953 = clamp(half(sqrt(sqrt(fast::min(fma(float(_876), float(_876), fast::min((dot(_863, _863) + dot(_865, _865)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half3 _929 = reflect(-half3(_643), _1774);
    float4 _960 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1774, half3(_643)), half(9.9999997473787516355514526367188e-05)), _953)), level(0.0));
    half3 _969 = mix(half4(_960).xxx, half4(_960).yyy, half3(float3(params.facet_f0)));
    float4 _979 = facet_environment.sample(facet_environmentSmplr, float3(_929), level(_953 * (half(4.0) * (half(2.0) - _953))));
    half3 _692 = half4(frame.lightDirection).xyz;
    half _1119 = clamp(dot(_929, _692), half(0.0), half(1.0));
    half _1122 = _1119 * _1119;
    half4 _1832 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1122 * _1122, _953), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1134 = _1832.x;
    float3 _1179 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1182 = dot(_1179, _1179);
    float3 _1187 = _1179 * rsqrt(fast::max(_1182, 9.9999999392252902907785028219223e-09));
    float _1191 = _1182 * float(frame.punctualLights[0].positionFalloff.w);
    float _1196 = fast::clamp(fma(-_1191, _1191, 1.0), 0.0, 1.0);
    float _1215 = fast::clamp(fma(dot(-_1187, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1358 = clamp(dot(_929, half3(_1187)), half(0.0), half(1.0));
    half _1361 = _1358 * _1358;
    half4 _1856 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1361 * _1361, _953), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1373 = _1856.x;
    float3 _1418 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1421 = dot(_1418, _1418);
    float3 _1426 = _1418 * rsqrt(fast::max(_1421, 9.9999999392252902907785028219223e-09));
    float _1430 = _1421 * float(frame.punctualLights[1].positionFalloff.w);
    float _1435 = fast::clamp(fma(-_1430, _1430, 1.0), 0.0, 1.0);
    float _1454 = fast::clamp(fma(dot(-_1426, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1597 = clamp(dot(_929, half3(_1426)), half(0.0), half(1.0));
    half _1600 = _1597 * _1597;
    half4 _1881 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1600 * _1600, _953), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1612 = _1881.x;
    half3 _1621 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_979).xyz * _969) + min((_969 * ((_1134 * _1134) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_1774, _692), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_969 * ((_1373 * _1373) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1196) * half(_1196)) / fast::max(_1182, 9.9999997473787516355514526367188e-05)) * half(_1215)) * half(_1215)), float3(65504.0))) * clamp(dot(_1774, half3(_1187)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_969 * ((_1612 * _1612) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1435) * half(_1435)) / fast::max(_1421, 9.9999997473787516355514526367188e-05)) * half(_1454)) * half(_1454)), float3(65504.0))) * clamp(dot(_1774, half3(_1426)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1621, half(1.0)));
    return out;
}

