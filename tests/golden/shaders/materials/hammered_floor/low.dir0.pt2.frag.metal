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
    float4 _779 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _783 = (half4(_779).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1596;
    do
    {
        half3 _796 = half4(in.v_tangent).xyz;
        if (float(dot(_796, _796)) == 0.0)
        {
            _1596 = normalize(half3(in.v_normal));
            break;
        }
        _1596 = normalize(((_796 * _783.x) + ((cross(half3(in.v_normal), _796) * half(in.v_tangent.w)) * _783.y)) + (half3(in.v_normal) * _783.z));
        break;
    } while(false);
    half _832 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _842 = dfdx(float3(_1596));
    float3 _844 = dfdy(float3(_1596));
    half _855 = _832 * _832;
    half _932 = clamp(half(sqrt(sqrt(fast::min(fma(float(_855), float(_855), fast::min((dot(_842, _842) + dot(_844, _844)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half3 _908 = reflect(-half3(_643), _1596);
    float4 _939 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_1596, half3(_643)), half(9.9999997473787516355514526367188e-05)), _932)), level(0.0));
    half3 _948 = mix(half4(_939).xxx, half4(_939).yyy, half3(float3(params.facet_f0)));
    float4 _958 = facet_environment.sample(facet_environmentSmplr, float3(_908), level(_932 * (half(4.0) * (half(2.0) - _932))));
    float3 _1003 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1006 = dot(_1003, _1003);
    float3 _1011 = _1003 * rsqrt(fast::max(_1006, 9.9999999392252902907785028219223e-09));
    float _1015 = _1006 * float(frame.punctualLights[0].positionFalloff.w);
    float _1020 = fast::clamp(fma(-_1015, _1015, 1.0), 0.0, 1.0);
    float _1039 = fast::clamp(fma(dot(-_1011, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1182 = clamp(dot(_908, half3(_1011)), half(0.0), half(1.0));
    half _1185 = _1182 * _1182;
    half4 _1665 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1185 * _1185, _932), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1197 = _1665.x;
    float3 _1242 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1245 = dot(_1242, _1242);
    float3 _1250 = _1242 * rsqrt(fast::max(_1245, 9.9999999392252902907785028219223e-09));
    float _1254 = _1245 * float(frame.punctualLights[1].positionFalloff.w);
    float _1259 = fast::clamp(fma(-_1254, _1254, 1.0), 0.0, 1.0);
    float _1278 = fast::clamp(fma(dot(-_1250, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1421 = clamp(dot(_908, half3(_1250)), half(0.0), half(1.0));
    half _1424 = _1421 * _1421;
    half4 _1690 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1424 * _1424, _932), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1436 = _1690.x;
    half3 _1445 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_958).xyz * _948) + min((_948 * ((_1197 * _1197) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1020) * half(_1020)) / fast::max(_1006, 9.9999997473787516355514526367188e-05)) * half(_1039)) * half(_1039)), float3(65504.0))) * clamp(dot(_1596, half3(_1011)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_948 * ((_1436 * _1436) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1259) * half(_1259)) / fast::max(_1245, 9.9999997473787516355514526367188e-05)) * half(_1278)) * half(_1278)), float3(65504.0))) * clamp(dot(_1596, half3(_1250)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1445, half(1.0)));
    return out;
}

