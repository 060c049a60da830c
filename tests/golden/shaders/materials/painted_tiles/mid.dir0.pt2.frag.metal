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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _677 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _804 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _807 = facet_material_albedo.sample(facet_material_albedoSmplr, _804);
    float4 _817 = facet_material_relief.sample(facet_material_reliefSmplr, _804);
    half3 _821 = (half4(_817).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1690;
    do
    {
        half3 _834 = half4(in.v_tangent).xyz;
        if (float(dot(_834, _834)) == 0.0)
        {
            _1690 = normalize(half3(in.v_normal));
            break;
        }
        _1690 = normalize(((_834 * _821.x) + ((cross(half3(in.v_normal), _834) * half(in.v_tangent.w)) * _821.y)) + (half3(in.v_normal) * _821.z));
        break;
    } while(false);
    half _912 = max(dot(_1690, half3(_677)), half(9.9999997473787516355514526367188e-05));
    float4 _975 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_912, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _994 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_975).y) - half(1.0)));
    float4 _1001 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_677), _1690)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1046 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1049 = dot(_1046, _1046);
    float3 _1054 = _1046 * rsqrt(fast::max(_1049, 9.9999999392252902907785028219223e-09));
    float _1058 = _1049 * float(frame.punctualLights[0].positionFalloff.w);
    float _1063 = fast::clamp(fma(-_1058, _1058, 1.0), 0.0, 1.0);
    float _1082 = fast::clamp(fma(dot(-_1054, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1216 = normalize(half3(_677) + half3(_1054));
    half _1143 = clamp(dot(_1690, half3(_1054)), half(0.0), half(1.0));
    half3 _1243 = cross(_1690, _1216);
    half _1246 = clamp(dot(_1690, _1216), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1263 = max(mix((half(2.0) * _1143) * _912, _1143 + _912, half(params.facet_alpha)), half(0.000244140625));
    half _1265 = half(1024.0) * half(params.facet_alpha);
    half _1270 = _1265 / (fma(_1246, _1246, dot(_1243, _1243)) * (half(6433.98193359375) * _1263));
    float3 _1318 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1321 = dot(_1318, _1318);
    float3 _1326 = _1318 * rsqrt(fast::max(_1321, 9.9999999392252902907785028219223e-09));
    float _1330 = _1321 * float(frame.punctualLights[1].positionFalloff.w);
    float _1335 = fast::clamp(fma(-_1330, _1330, 1.0), 0.0, 1.0);
    float _1354 = fast::clamp(fma(dot(-_1326, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1488 = normalize(half3(_677) + half3(_1326));
    half _1415 = clamp(dot(_1690, half3(_1326)), half(0.0), half(1.0));
    half3 _1515 = cross(_1690, _1488);
    half _1518 = clamp(dot(_1690, _1488), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1535 = max(mix((half(2.0) * _1415) * _912, _1415 + _912, half(params.facet_alpha)), half(0.000244140625));
    half _1542 = _1265 / (fma(_1518, _1518, dot(_1515, _1515)) * (half(6433.98193359375) * _1535));
    half3 _1554 = (fma(clamp(half4(_807).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_1001).xyz * (mix(half4(_975).xxx, half4(_975).yyy, half3(float3(0.039999999105930328369140625))) * _994)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1270 * (_1270 * (half(6.283185482025146484375) * _1263)), half(65504.0))) * _994) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1063) * half(_1063)) / fast::max(_1049, 9.9999997473787516355514526367188e-05)) * half(_1082)) * half(_1082)), float3(65504.0))) * _1143), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1542 * (_1542 * (half(6.283185482025146484375) * _1535)), half(65504.0))) * _994) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1335) * half(_1335)) / fast::max(_1321, 9.9999997473787516355514526367188e-05)) * half(_1354)) * half(_1354)), float3(65504.0))) * _1415), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1554, half(1.0)));
    return out;
}

