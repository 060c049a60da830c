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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _877 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _1007 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _1011 = (half4(_1007).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _2147;
    do
    {
        half3 _1024 = half4(in.v_tangent).xyz;
        if (float(dot(_1024, _1024)) == 0.0)
        {
            _2147 = normalize(half3(in.v_normal));
            break;
        }
        _2147 = normalize(((_1024 * _1011.x) + ((cross(half3(in.v_normal), _1024) * half(in.v_tangent.w)) * _1011.y)) + (half3(in.v_normal) * _1011.z));
        break;
    } while(false);
    half _1060 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _1070 = dfdx(float3(_2147));
    float3 _1072 = dfdy(float3(_2147));
    half _1083 = _1060 * _1060;
    half3 _1201 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _2147.y)) + (half4(frame.sh[2]).xyz * _2147.z)) + (half4(frame.sh[3]).xyz * _2147.x)) + (((((half4(frame.sh[4]).xyz * (_2147.x * _2147.y)) + (half4(frame.sh[5]).xyz * (_2147.y * _2147.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _2147.z, _2147.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_2147.x * _2147.z))) + (half4(frame.sh[8]).xyz * fma(_2147.x, _2147.x, half(-float(_2147.y * _2147.y))))), half3(float3(0.0)));
    half _1284 = clamp(half(sqrt(sqrt(fast::min(fma(float(_1083), float(_1083), fast::min((dot(_1070, _1070) + dot(_1072, _1072)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1251 = max(dot(_2147, half3(_877)), half(9.9999997473787516355514526367188e-05));
    float4 _1291 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1251, _1284)), level(0.0));
    half3 _1310 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1291).y) - half(1.0)));
    float4 _1317 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_877), _2147)), level(_1284 * half(4.0)));
    float3 _1362 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1365 = dot(_1362, _1362);
    float3 _1370 = _1362 * rsqrt(fast::max(_1365, 9.9999999392252902907785028219223e-09));
    float _1374 = _1365 * float(frame.punctualLights[0].positionFalloff.w);
    float _1379 = fast::clamp(fma(-_1374, _1374, 1.0), 0.0, 1.0);
    float _1398 = fast::clamp(fma(dot(-_1370, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1516 = _1284 * _1284;
    float3 _1528 = fast::normalize(_877 + _1370);
    half _1461 = clamp(dot(_2147, half3(_1370)), half(0.0), half(1.0));
    half3 _1568 = cross(_2147, half3(_1528));
    half _1571 = clamp(dot(_2147, half3(_1528)), half(0.0), half(1.0)) * _1516;
    half _1580 = _1516 / fma(_1571, _1571, dot(_1568, _1568));
    half _1594 = _1516 * _1516;
    half _1600 = fma(half(-float(_1516)), _1516, half(1.0));
    half _1604 = sqrt(fma(_1251 * _1251, _1600, _1594));
    half _1628 = half(1.0) - clamp(dot(half3(_1370), half3(_1528)), half(0.0), half(1.0));
    half _1631 = _1628 * _1628;
    half3 _1639 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1492 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1689 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1692 = dot(_1689, _1689);
    float3 _1697 = _1689 * rsqrt(fast::max(_1692, 9.9999999392252902907785028219223e-09));
    float _1701 = _1692 * float(frame.punctualLights[1].positionFalloff.w);
    float _1706 = fast::clamp(fma(-_1701, _1701, 1.0), 0.0, 1.0);
    float _1725 = fast::clamp(fma(dot(-_1697, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1855 = fast::normalize(_877 + _1697);
    half _1788 = clamp(dot(_2147, half3(_1697)), half(0.0), half(1.0));
    half3 _1895 = cross(_2147, half3(_1855));
    half _1898 = clamp(dot(_2147, half3(_1855)), half(0.0), half(1.0)) * _1516;
    half _1907 = _1516 / fma(_1898, _1898, dot(_1895, _1895));
    half _1955 = half(1.0) - clamp(dot(half3(_1697), half3(_1855)), half(0.0), half(1.0));
    half _1958 = _1955 * _1955;
    half3 _1980 = (fma(half3(float3(params.facet_diffuseColor)), _1201, half4(_1317).xyz * (mix(half4(_1291).xxx, half4(_1291).yyy, half3(float3(params.facet_f0))) * _1310)) + min(fma((half3(float3(params.facet_f0)) + (_1639 * ((_1631 * _1631) * _1628))) * min(min((_1580 * _1580) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1461, _1604, _1251 * sqrt(fma(_1461 * _1461, _1600, _1594))), half(65504.0)), half(65504.0)), _1310, _1492) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1379) * half(_1379)) / fast::max(_1365, 9.9999997473787516355514526367188e-05)) * half(_1398)) * half(_1398)), float3(65504.0))) * _1461), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1639 * ((_1958 * _1958) * _1955))) * min(min((_1907 * _1907) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1788, _1604, _1251 * sqrt(fma(_1788 * _1788, _1600, _1594))), half(65504.0)), half(65504.0)), _1310, _1492) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1706) * half(_1706)) / fast::max(_1692, 9.9999997473787516355514526367188e-05)) * half(_1725)) * half(_1725)), float3(65504.0))) * _1788), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1980, half(1.0)));
    return out;
}

