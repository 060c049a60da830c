#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    half3 _759 = normalize(half3(in.v_normal));
    float3 _775 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _935 = max(dot(_759, half3(_775)), half(9.9999997473787516355514526367188e-05));
    half3 _939 = reflect(-half3(_775), _759);
    float4 _974 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_935, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _993 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_974).y) - half(1.0)));
    float4 _1003 = facet_environment.sample(facet_environmentSmplr, float3(_939), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1080 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1037 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_935, _1080)), level(0.0));
    half3 _1087 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1917 = half4(_1037);
    half _1050 = _1917.z;
    half _1052 = fma(half(-float(max(_1087.x, max(_1087.y, _1087.z)))), _1050, half(1.0));
    half _1096 = _1080 * _1080;
    half4 _1921 = half4(_1037);
    half _1057 = _1921.w;
    float4 _1111 = facet_environment.sample(facet_environmentSmplr, float3(_939), level(_1080 * (half(4.0) * (half(2.0) - _1080))));
    float3 _1148 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1151 = dot(_1148, _1148);
    float3 _1156 = _1148 * rsqrt(fast::max(_1151, 9.9999999392252902907785028219223e-09));
    float _1160 = _1151 * float(frame.punctualLights[0].positionFalloff.w);
    float _1165 = fast::clamp(fma(-_1160, _1160, 1.0), 0.0, 1.0);
    float _1184 = fast::clamp(fma(dot(-_1156, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1195 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1165) * half(_1165)) / fast::max(_1151, 9.9999997473787516355514526367188e-05)) * half(_1184)) * half(_1184)), float3(65504.0));
    half3 _1311 = normalize(half3(_775) + half3(_1156));
    half _1250 = clamp(dot(_759, half3(_1156)), half(0.0), half(1.0));
    half _1254 = clamp(dot(_759, _1311), half(0.0), half(1.0));
    half3 _1338 = cross(_759, _1311);
    half _1341 = _1254 * half(params.facet_alpha);
    half _1355 = _1250 + _935;
    half _1358 = max(mix((half(2.0) * _1250) * _935, _1355, half(params.facet_alpha)), half(0.000244140625));
    half _1360 = half(1024.0) * half(params.facet_alpha);
    half _1365 = _1360 / (fma(_1341, _1341, dot(_1338, _1338)) * (half(6433.98193359375) * _1358));
    half _1402 = half(8192.0) * fma(half(-float(_1250)), _935, _1355);
    half _1406 = half(1.0) / (_1096 * _1402);
    half _1413 = half(2048.0) * _1096;
    float3 _1471 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1474 = dot(_1471, _1471);
    float3 _1479 = _1471 * rsqrt(fast::max(_1474, 9.9999999392252902907785028219223e-09));
    float _1483 = _1474 * float(frame.punctualLights[1].positionFalloff.w);
    float _1488 = fast::clamp(fma(-_1483, _1483, 1.0), 0.0, 1.0);
    float _1507 = fast::clamp(fma(dot(-_1479, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1518 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1488) * half(_1488)) / fast::max(_1474, 9.9999997473787516355514526367188e-05)) * half(_1507)) * half(_1507)), float3(65504.0));
    half3 _1634 = normalize(half3(_775) + half3(_1479));
    half _1573 = clamp(dot(_759, half3(_1479)), half(0.0), half(1.0));
    half _1577 = clamp(dot(_759, _1634), half(0.0), half(1.0));
    half3 _1661 = cross(_759, _1634);
    half _1664 = _1577 * half(params.facet_alpha);
    half _1678 = _1573 + _935;
    half _1681 = max(mix((half(2.0) * _1573) * _935, _1678, half(params.facet_alpha)), half(0.000244140625));
    half _1688 = _1360 / (fma(_1664, _1664, dot(_1661, _1661)) * (half(6433.98193359375) * _1681));
    half _1725 = half(8192.0) * fma(half(-float(_1573)), _935, _1678);
    half _1729 = half(1.0) / (_1096 * _1725);
    half3 _1758 = (fma(half4(_1111).xyz, _1087 * _1050, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1003).xyz * (mix(half4(_974).xxx, half4(_974).yyy, half3(float3(params.facet_f0))) * _993)) * _1052) + min(fma((half3(float3(params.facet_f0)) * min(_1365 * (_1365 * (half(6.283185482025146484375) * _1358)), half(65504.0))) * _993, (half3(_1195) * _1250) * _1052, (_1087 * ((((fma(_1406, _1402, half(2.0)) * pow(max(fma(half(-float(_1254)), _1254, half(1.0)), half(0.0)), half(0.5) * (_1406 * _1402))) * half(0.15915493667125701904296875)) * (_1250 * (_1406 * _1413))) * _1057)) * half3(_1195)), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1688 * (_1688 * (half(6.283185482025146484375) * _1681)), half(65504.0))) * _993, (half3(_1518) * _1573) * _1052, (_1087 * ((((fma(_1729, _1725, half(2.0)) * pow(max(fma(half(-float(_1577)), _1577, half(1.0)), half(0.0)), half(0.5) * (_1729 * _1725))) * half(0.15915493667125701904296875)) * (_1573 * (_1729 * _1413))) * _1057)) * half3(_1518)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1758, half(1.0)));
    return out;
}

