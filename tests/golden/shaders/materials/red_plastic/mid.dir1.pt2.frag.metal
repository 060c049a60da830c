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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _559 = normalize(half3(in.v_normal));
    float3 _575 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _744 = max(dot(_559, half3(_575)), half(9.9999997473787516355514526367188e-05));
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_744, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _802 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_783).y) - half(1.0)));
    float4 _814 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_575), _559)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _612 = half4(frame.lightDirection).xyz;
    half3 _921 = normalize(half3(_575) + _612);
    half _872 = clamp(dot(_559, _612), half(0.0), half(1.0));
    half3 _948 = cross(_559, _921);
    half _951 = clamp(dot(_559, _921), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _968 = max(mix((half(2.0) * _872) * _744, _872 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _970 = half(1024.0) * half(params.facet_alpha);
    half _975 = _970 / (fma(_951, _951, dot(_948, _948)) * (half(6433.98193359375) * _968));
    float3 _1023 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1026 = dot(_1023, _1023);
    float3 _1031 = _1023 * rsqrt(fast::max(_1026, 9.9999999392252902907785028219223e-09));
    float _1035 = _1026 * float(frame.punctualLights[0].positionFalloff.w);
    float _1040 = fast::clamp(fma(-_1035, _1035, 1.0), 0.0, 1.0);
    float _1059 = fast::clamp(fma(dot(-_1031, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1169 = normalize(half3(_575) + half3(_1031));
    half _1120 = clamp(dot(_559, half3(_1031)), half(0.0), half(1.0));
    half3 _1196 = cross(_559, _1169);
    half _1199 = clamp(dot(_559, _1169), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1216 = max(mix((half(2.0) * _1120) * _744, _1120 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1223 = _970 / (fma(_1199, _1199, dot(_1196, _1196)) * (half(6433.98193359375) * _1216));
    float3 _1271 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1274 = dot(_1271, _1271);
    float3 _1279 = _1271 * rsqrt(fast::max(_1274, 9.9999999392252902907785028219223e-09));
    float _1283 = _1274 * float(frame.punctualLights[1].positionFalloff.w);
    float _1288 = fast::clamp(fma(-_1283, _1283, 1.0), 0.0, 1.0);
    float _1307 = fast::clamp(fma(dot(-_1279, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1417 = normalize(half3(_575) + half3(_1279));
    half _1368 = clamp(dot(_559, half3(_1279)), half(0.0), half(1.0));
    half3 _1444 = cross(_559, _1417);
    half _1447 = clamp(dot(_559, _1417), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1464 = max(mix((half(2.0) * _1368) * _744, _1368 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1471 = _970 / (fma(_1447, _1447, dot(_1444, _1444)) * (half(6433.98193359375) * _1464));
    half3 _1483 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_814).xyz * (mix(half4(_783).xxx, half4(_783).yyy, half3(float3(params.facet_f0))) * _802)) + min(((half3(float3(params.facet_f0)) * min(_975 * (_975 * (half(6.283185482025146484375) * _968)), half(65504.0))) * _802) * (half4(frame.lightColor).xyz * _872), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1223 * (_1223 * (half(6.283185482025146484375) * _1216)), half(65504.0))) * _802) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1040) * half(_1040)) / fast::max(_1026, 9.9999997473787516355514526367188e-05)) * half(_1059)) * half(_1059)), float3(65504.0))) * _1120), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1471 * (_1471 * (half(6.283185482025146484375) * _1464)), half(65504.0))) * _802) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1288) * half(_1288)) / fast::max(_1274, 9.9999997473787516355514526367188e-05)) * half(_1307)) * half(_1307)), float3(65504.0))) * _1368), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1483, half(1.0)));
    return out;
}

