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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _775 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _928 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _931 = facet_material_albedo.sample(facet_material_albedoSmplr, _928);
    float4 _941 = facet_material_relief.sample(facet_material_reliefSmplr, _928);
    half3 _945 = (half4(_941).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _951 = fract(_928 * 4.0);
    float _953 = _951.x;
    float _960 = _951.y;
    half3 _1885;
    do
    {
        half3 _985 = half4(in.v_tangent).xyz;
        if (float(dot(_985, _985)) == 0.0)
        {
            _1885 = normalize(half3(in.v_normal));
            break;
        }
        _1885 = normalize(((_985 * _945.x) + ((cross(half3(in.v_normal), _985) * half(in.v_tangent.w)) * _945.y)) + (half3(in.v_normal) * _945.z));
        break;
    } while(false);
    half3 _1028 = clamp(half4(_931).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1037 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_953, 1.0 - _953), fast::min(_960, 1.0 - _960))))), half(0.0), half(1.0));
    half3 _1130 = reflect(-half3(_775), _1885);
    half4 _1185 = (half4(float4(-1.0, -0.0274999998509883880615234375, -0.572000026702880859375, 0.02199999988079071044921875)) * half(params.facet_perceptualRoughness)) + half4(float4(1.0, 0.0425000004470348358154296875, 1.03999996185302734375, -0.039999999105930328369140625));
    half _1187 = _1185.x;
    half2 _1205 = (half2(float2(-1.03999996185302734375, 1.03999996185302734375)) * fma(min(_1187 * _1187, exp2(half(-9.27999973297119140625) * max(dot(_1885, half3(_775)), half(9.9999997473787516355514526367188e-05)))), _1187, _1185.y)) + _1185.zw;
    half3 _1213 = (half3(float3(0.039999999105930328369140625)) * _1205.x) + half3(_1205.y);
    float4 _1223 = facet_environment.sample(facet_environmentSmplr, float3(_1130), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1274 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1277 = dot(_1274, _1274);
    float3 _1282 = _1274 * rsqrt(fast::max(_1277, 9.9999999392252902907785028219223e-09));
    float _1286 = _1277 * float(frame.punctualLights[0].positionFalloff.w);
    float _1291 = fast::clamp(fma(-_1286, _1286, 1.0), 0.0, 1.0);
    float _1310 = fast::clamp(fma(dot(-_1282, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1466 = clamp(dot(_1130, half3(_1282)), half(0.0), half(1.0));
    half _1469 = _1466 * _1466;
    half4 _1970 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1469 * _1469, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1481 = _1970.x;
    float3 _1526 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1529 = dot(_1526, _1526);
    float3 _1534 = _1526 * rsqrt(fast::max(_1529, 9.9999999392252902907785028219223e-09));
    float _1538 = _1529 * float(frame.punctualLights[1].positionFalloff.w);
    float _1543 = fast::clamp(fma(-_1538, _1538, 1.0), 0.0, 1.0);
    float _1562 = fast::clamp(fma(dot(-_1534, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1718 = clamp(dot(_1130, half3(_1534)), half(0.0), half(1.0));
    half _1721 = _1718 * _1718;
    half4 _1996 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1721 * _1721, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1733 = _1996.x;
    half3 _1742 = ((fma(_1028 * half3(in.v_diffuseLight), max(half3(_1037), ((((((_1028 * half(2.040400028228759765625)) - half3(float3(0.3323999941349029541015625))) * _1037) + ((_1028 * half(-4.79510021209716796875)) + half3(float3(0.6417000293731689453125)))) * _1037) + ((_1028 * half(2.755199909210205078125)) + half3(float3(0.69029998779296875)))) * _1037), _1028 * half3(in.v_directDiffuse)) + ((half4(_1223).xyz * _1213) * _1037)) + min((_1213 * ((_1481 * _1481) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1291) * half(_1291)) / fast::max(_1277, 9.9999997473787516355514526367188e-05)) * half(_1310)) * half(_1310)), float3(65504.0))) * clamp(dot(_1885, half3(_1282)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_1213 * ((_1733 * _1733) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1543) * half(_1543)) / fast::max(_1529, 9.9999997473787516355514526367188e-05)) * half(_1562)) * half(_1562)), float3(65504.0))) * clamp(dot(_1885, half3(_1534)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1742, half(1.0)));
    return out;
}

