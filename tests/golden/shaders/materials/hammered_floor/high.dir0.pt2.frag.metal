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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_relief [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_reliefSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _875 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1005 = facet_material_relief.sample(facet_material_reliefSmplr, (in.v_uv0 * params.tiling));
    half3 _1009 = (half4(_1005).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2143;
    do
    {
        half3 _1022 = half4(in.v_tangent).xyz;
        if (float(dot(_1022, _1022)) == 0.0)
        {
            _2143 = normalize(half3(in.v_normal));
            break;
        }
        _2143 = normalize(((_1022 * _1009.x) + ((cross(half3(in.v_normal), _1022) * half(in.v_tangent.w)) * _1009.y)) + (half3(in.v_normal) * _1009.z));
        break;
    } while(false);
    half _1058 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _1067 = dfdx(float3(_2143));
    float3 _1069 = dfdy(float3(_2143));
    half _1080 = _1058 * _1058;
    half3 _1197 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2143.y)) + (half4(frame.sh[2]).xyz * _2143.z)) + (half4(frame.sh[3]).xyz * _2143.x)) + (((((half4(frame.sh[4]).xyz * (_2143.x * _2143.y)) + (half4(frame.sh[5]).xyz * (_2143.y * _2143.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2143.z, _2143.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2143.x * _2143.z))) + (half4(frame.sh[8]).xyz * fma(_2143.x, _2143.x, half(-float(_2143.y * _2143.y))))), half3(float3(0.0)));
    half _1280 = clamp(sqrt(sqrt(min(fma(_1080, _1080, min((dot(half3(_1067), half3(_1067)) + dot(half3(_1069), half3(_1069))) * half(0.300000011920928955078125), half(0.20000000298023223876953125))), half(1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1247 = max(dot(_2143, half3(_875)), half(9.9999997473787516355514526367188e-05));
    float4 _1287 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1247, _1280)), level(0.0));
    half3 _1306 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1287).y) - half(1.0)));
    float4 _1313 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_875), _2143)), level(_1280 * half(4.0)));
    float3 _1358 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1361 = dot(_1358, _1358);
    float3 _1366 = _1358 * rsqrt(fast::max(_1361, 9.9999999392252902907785028219223e-09));
    float _1370 = _1361 * float(frame.punctualLights[0].positionFalloff.w);
    float _1375 = fast::clamp(fma(-_1370, _1370, 1.0), 0.0, 1.0);
    float _1394 = fast::clamp(fma(dot(-_1366, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1512 = _1280 * _1280;
    float3 _1524 = fast::normalize(_875 + _1366);
    half _1457 = clamp(dot(_2143, half3(_1366)), half(0.0), half(1.0));
    half3 _1564 = cross(_2143, half3(_1524));
    half _1567 = clamp(dot(_2143, half3(_1524)), half(0.0), half(1.0)) * _1512;
    half _1576 = _1512 / fma(_1567, _1567, dot(_1564, _1564));
    half _1590 = _1512 * _1512;
    half _1596 = fma(half(-float(_1512)), _1512, half(1.0));
    half _1600 = sqrt(fma(_1247 * _1247, _1596, _1590));
    half _1624 = half(1.0) - clamp(dot(half3(_1366), half3(_1524)), half(0.0), half(1.0));
    half _1627 = _1624 * _1624;
    half3 _1635 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1488 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1685 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1688 = dot(_1685, _1685);
    float3 _1693 = _1685 * rsqrt(fast::max(_1688, 9.9999999392252902907785028219223e-09));
    float _1697 = _1688 * float(frame.punctualLights[1].positionFalloff.w);
    float _1702 = fast::clamp(fma(-_1697, _1697, 1.0), 0.0, 1.0);
    float _1721 = fast::clamp(fma(dot(-_1693, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1851 = fast::normalize(_875 + _1693);
    half _1784 = clamp(dot(_2143, half3(_1693)), half(0.0), half(1.0));
    half3 _1891 = cross(_2143, half3(_1851));
    half _1894 = clamp(dot(_2143, half3(_1851)), half(0.0), half(1.0)) * _1512;
    half _1903 = _1512 / fma(_1894, _1894, dot(_1891, _1891));
    half _1951 = half(1.0) - clamp(dot(half3(_1693), half3(_1851)), half(0.0), half(1.0));
    half _1954 = _1951 * _1951;
    half3 _1976 = (fma(half3(float3(params.facet_diffuseColor)), _1197, half4(_1313).xyz * (mix(half4(_1287).xxx, half4(_1287).yyy, half3(float3(params.facet_f0))) * _1306)) + min(fma((half3(float3(params.facet_f0)) + (_1635 * ((_1627 * _1627) * _1624))) * min(min((_1576 * _1576) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1457, _1600, _1247 * sqrt(fma(_1457 * _1457, _1596, _1590))), half(65504.0)), half(65504.0)), _1306, _1488) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1375) * half(_1375)) / fast::max(_1361, 9.9999997473787516355514526367188e-05)) * half(_1394)) * half(_1394)), float3(65504.0))) * _1457), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1635 * ((_1954 * _1954) * _1951))) * min(min((_1903 * _1903) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1784, _1600, _1247 * sqrt(fma(_1784 * _1784, _1596, _1590))), half(65504.0)), half(65504.0)), _1306, _1488) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1702) * half(_1702)) / fast::max(_1688, 9.9999997473787516355514526367188e-05)) * half(_1721)) * half(_1721)), float3(65504.0))) * _1784), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1976, half(1.0)));
    return out;
}

