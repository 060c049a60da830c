#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _759 = fast::normalize(in.v_normal);
    float3 _765 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _899 = _759.y;
    float _904 = _759.z;
    float _909 = _759.x;
    float _1025 = fast::max(dot(_759, _765), 9.9999997473787516355514526367188e-05);
    float4 _1067 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1025, params.facet_perceptualRoughness), level(0.0));
    float3 _1086 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1067.y) - 1.0));
    float3 _1129 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1132 = dot(_1129, _1129);
    float3 _1137 = _1129 * rsqrt(fast::max(_1132, 9.9999999392252902907785028219223e-09));
    float _1141 = _1132 * float(frame.punctualLights[0].positionFalloff.w);
    float _1146 = fast::clamp(fma(-_1141, _1141, 1.0), 0.0, 1.0);
    float _1165 = fast::clamp(fma(dot(-_1137, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1222 = fast::clamp(dot(_759, _1137), 0.0, 1.0);
    float3 _1280 = fast::normalize(_765 + _1137);
    float _1318 = 4096.0 * params.facet_alpha;
    float4 _1342 = float4(cross(_759, _1280), params.facet_alpha * fast::clamp(dot(_759, _1280), 0.0, 1.0)) * 64.0;
    float _1324 = _1318 / dot(_1342, _1342);
    float _1353 = params.facet_alpha * params.facet_alpha;
    float _1359 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1363 = sqrt(fma(_1025 * _1025, _1359, _1353));
    float _1386 = 1.0 - fast::clamp(dot(_1137, _1280), 0.0, 1.0);
    float _1389 = _1386 * _1386;
    float3 _1397 = float3(1.0) - float3(params.facet_f0);
    float3 _1256 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1411 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _899)) + (frame.sh[2].xyz * _904)) + (frame.sh[3].xyz * _909)) + (((((frame.sh[4].xyz * (_909 * _899)) + (frame.sh[5].xyz * (_899 * _904))) + (frame.sh[6].xyz * fma(3.0 * _904, _904, -1.0))) + (frame.sh[7].xyz * (_909 * _904))) + (frame.sh[8].xyz * fma(_909, _909, -(_899 * _899)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_765, _759), level(params.facet_environmentLod)).xyz * (mix(_1067.xxx, _1067.yyy, float3(params.facet_f0)) * _1086)) + fast::min(fma((float3(params.facet_f0) + (_1397 * ((_1389 * _1389) * _1386))) * (((_1324 * _1324) * 0.3183098733425140380859375) * (0.5 / fma(_1222, _1363, _1025 * sqrt(fma(_1222 * _1222, _1359, _1353))))), _1086, _1256) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1146 * _1146) / fast::max(_1132, 9.9999997473787516355514526367188e-05)) * _1165) * _1165)) * _1222), float3(65504.0));
    float3 _1446 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1449 = dot(_1446, _1446);
    float3 _1454 = _1446 * rsqrt(fast::max(_1449, 9.9999999392252902907785028219223e-09));
    float _1458 = _1449 * float(frame.punctualLights[1].positionFalloff.w);
    float _1463 = fast::clamp(fma(-_1458, _1458, 1.0), 0.0, 1.0);
    float _1482 = fast::clamp(fma(dot(-_1454, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1539 = fast::clamp(dot(_759, _1454), 0.0, 1.0);
    float3 _1597 = fast::normalize(_765 + _1454);
    float4 _1659 = float4(cross(_759, _1597), params.facet_alpha * fast::clamp(dot(_759, _1597), 0.0, 1.0)) * 64.0;
    float _1641 = _1318 / dot(_1659, _1659);
    float _1703 = 1.0 - fast::clamp(dot(_1454, _1597), 0.0, 1.0);
    float _1706 = _1703 * _1703;
    out.fragColor = float4(_1411 + fast::min(fma((float3(params.facet_f0) + (_1397 * ((_1706 * _1706) * _1703))) * (((_1641 * _1641) * 0.3183098733425140380859375) * (0.5 / fma(_1539, _1363, _1025 * sqrt(fma(_1539 * _1539, _1359, _1353))))), _1086, _1256) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1463 * _1463) / fast::max(_1449, 9.9999997473787516355514526367188e-05)) * _1482) * _1482)) * _1539), float3(65504.0)), 1.0);
    return out;
}

