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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _1010 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1145 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1148 = facet_material_albedo.sample(facet_material_albedoSmplr, _1145);
    float4 _1158 = facet_material_relief.sample(facet_material_reliefSmplr, _1145);
    float3 _1162 = (_1158.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1168 = fract(_1145 * 4.0);
    float _1170 = _1168.x;
    float _1177 = _1168.y;
    float3 _2428;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2428 = fast::normalize(in.v_normal);
            break;
        }
        _2428 = fast::normalize(((in.v_tangent.xyz * _1162.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1162.y)) + (in.v_normal * _1162.z));
        break;
    } while(false);
    float3 _1362 = fast::clamp(_1148.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1371 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1170, 1.0 - _1170), fast::min(_1177, 1.0 - _1177)))), 0.0, 1.0);
    float _1452 = fast::max(dot(_2428, _1010), 9.9999997473787516355514526367188e-05);
    float4 _1517 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1452, params.facet_perceptualRoughness), level(0.0));
    float3 _1536 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1517.y) - 1.0));
    float3 _1619 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1622 = dot(_1619, _1619);
    float3 _1627 = _1619 * rsqrt(fast::max(_1622, 9.9999999392252902907785028219223e-09));
    float _1631 = _1622 * float(frame.punctualLights[0].positionFalloff.w);
    float _1636 = fast::clamp(fma(-_1631, _1631, 1.0), 0.0, 1.0);
    float _1655 = fast::clamp(fma(dot(-_1627, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1794 = fast::normalize(_1010 + _1627);
    float _1715 = fast::clamp(dot(_2428, _1627), 0.0, 1.0);
    float3 _1832 = cross(_2428, _1794);
    float _1835 = fast::clamp(dot(_2428, _1794), 0.0, 1.0) * params.facet_alpha;
    float _1844 = params.facet_alpha / fma(_1835, _1835, dot(_1832, _1832));
    float _1857 = params.facet_alpha * params.facet_alpha;
    float _1863 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1867 = sqrt(fma(_1452 * _1452, _1863, _1857));
    float _1890 = 1.0 - fast::clamp(dot(_1627, _1794), 0.0, 1.0);
    float _1893 = _1890 * _1890;
    float3 _1746 = _1362 * 0.3183098733425140380859375;
    float3 _1923 = fma(_1362 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2428.y)) + (frame.sh[2].xyz * _2428.z)) + (frame.sh[3].xyz * _2428.x)) + (((((frame.sh[4].xyz * (_2428.x * _2428.y)) + (frame.sh[5].xyz * (_2428.y * _2428.z))) + (frame.sh[6].xyz * fma(3.0 * _2428.z, _2428.z, -1.0))) + (frame.sh[7].xyz * (_2428.x * _2428.z))) + (frame.sh[8].xyz * fma(_2428.x, _2428.x, -(_2428.y * _2428.y)))), float3(0.0)), fast::max(float3(_1371), ((((((_1362 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1371) + ((_1362 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1371) + ((_1362 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1371), (facet_environment.sample(facet_environmentSmplr, reflect(-_1010, _2428), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1517.xxx, _1517.yyy, float3(0.039999999105930328369140625)) * _1536)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1452 + _1371)) - 1.0) + _1371, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1893 * _1893) * _1890))) * (((_1844 * _1844) * 0.3183098733425140380859375) * (0.5 / fma(_1715, _1867, _1452 * sqrt(fma(_1715 * _1715, _1863, _1857))))), _1536, _1746) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1636 * _1636) / fast::max(_1622, 9.9999997473787516355514526367188e-05)) * _1655) * _1655)) * _1715), float3(65504.0));
    float3 _1958 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1961 = dot(_1958, _1958);
    float3 _1966 = _1958 * rsqrt(fast::max(_1961, 9.9999999392252902907785028219223e-09));
    float _1970 = _1961 * float(frame.punctualLights[1].positionFalloff.w);
    float _1975 = fast::clamp(fma(-_1970, _1970, 1.0), 0.0, 1.0);
    float _1994 = fast::clamp(fma(dot(-_1966, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2133 = fast::normalize(_1010 + _1966);
    float _2054 = fast::clamp(dot(_2428, _1966), 0.0, 1.0);
    float3 _2171 = cross(_2428, _2133);
    float _2174 = fast::clamp(dot(_2428, _2133), 0.0, 1.0) * params.facet_alpha;
    float _2183 = params.facet_alpha / fma(_2174, _2174, dot(_2171, _2171));
    float _2229 = 1.0 - fast::clamp(dot(_1966, _2133), 0.0, 1.0);
    float _2232 = _2229 * _2229;
    out.fragColor = float4(_1923 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2232 * _2232) * _2229))) * (((_2183 * _2183) * 0.3183098733425140380859375) * (0.5 / fma(_2054, _1867, _1452 * sqrt(fma(_2054 * _2054, _1863, _1857))))), _1536, _1746) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1975 * _1975) / fast::max(_1961, 9.9999997473787516355514526367188e-05)) * _1994) * _1994)) * _2054), float3(65504.0)), 1.0);
    return out;
}

