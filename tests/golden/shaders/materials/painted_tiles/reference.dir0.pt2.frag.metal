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
    float3 _1013 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1148 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1151 = facet_material_albedo.sample(facet_material_albedoSmplr, _1148);
    float4 _1161 = facet_material_relief.sample(facet_material_reliefSmplr, _1148);
    float3 _1165 = (_1161.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1171 = fract(_1148 * 4.0);
    float _1173 = _1171.x;
    float _1180 = _1171.y;
    float3 _2434;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2434 = fast::normalize(in.v_normal);
            break;
        }
        _2434 = fast::normalize(((in.v_tangent.xyz * _1165.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1165.y)) + (in.v_normal * _1165.z));
        break;
    } while(false);
    float3 _1365 = fast::clamp(_1151.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1374 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1173, 1.0 - _1173), fast::min(_1180, 1.0 - _1180)))), 0.0, 1.0);
    float _1455 = fast::max(dot(_2434, _1013), 9.9999997473787516355514526367188e-05);
    float4 _1520 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1455, params.facet_perceptualRoughness), level(0.0));
    float3 _1539 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1520.y) - 1.0));
    float3 _1625 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1628 = dot(_1625, _1625);
    float3 _1633 = _1625 * rsqrt(fast::max(_1628, 9.9999999392252902907785028219223e-09));
    float _1637 = _1628 * float(frame.punctualLights[0].positionFalloff.w);
    float _1642 = fast::clamp(fma(-_1637, _1637, 1.0), 0.0, 1.0);
    float _1661 = fast::clamp(fma(dot(-_1633, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1800 = fast::normalize(_1013 + _1633);
    float _1721 = fast::clamp(dot(_2434, _1633), 0.0, 1.0);
    float3 _1838 = cross(_2434, _1800);
    float _1841 = fast::clamp(dot(_2434, _1800), 0.0, 1.0) * params.facet_alpha;
    float _1850 = params.facet_alpha / fma(_1841, _1841, dot(_1838, _1838));
    float _1863 = params.facet_alpha * params.facet_alpha;
    float _1869 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1873 = sqrt(fma(_1455 * _1455, _1869, _1863));
    float _1896 = 1.0 - fast::clamp(dot(_1633, _1800), 0.0, 1.0);
    float _1899 = _1896 * _1896;
    float3 _1752 = _1365 * 0.3183098733425140380859375;
    float3 _1929 = fma(_1365 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2434.y)) + (frame.sh[2].xyz * _2434.z)) + (frame.sh[3].xyz * _2434.x)) + (((((frame.sh[4].xyz * (_2434.x * _2434.y)) + (frame.sh[5].xyz * (_2434.y * _2434.z))) + (frame.sh[6].xyz * fma(3.0 * _2434.z, _2434.z, -1.0))) + (frame.sh[7].xyz * (_2434.x * _2434.z))) + (frame.sh[8].xyz * fma(_2434.x, _2434.x, -(_2434.y * _2434.y)))), float3(0.0)), fast::max(float3(_1374), ((((((_1365 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1374) + ((_1365 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1374) + ((_1365 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1374), (facet_environment.sample(facet_environmentSmplr, reflect(-_1013, _2434), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1520.xxx, _1520.yyy, float3(0.039999999105930328369140625)) * _1539)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1455 + _1374)) - 1.0) + _1374, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1899 * _1899) * _1896))) * (((_1850 * _1850) * 0.3183098733425140380859375) * (0.5 / fma(_1721, _1873, _1455 * sqrt(fma(_1721 * _1721, _1869, _1863))))), _1539, _1752) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1642 * _1642) / fast::max(_1628, 9.9999997473787516355514526367188e-05)) * _1661) * _1661)) * _1721), float3(65504.0));
    float3 _1964 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1967 = dot(_1964, _1964);
    float3 _1972 = _1964 * rsqrt(fast::max(_1967, 9.9999999392252902907785028219223e-09));
    float _1976 = _1967 * float(frame.punctualLights[1].positionFalloff.w);
    float _1981 = fast::clamp(fma(-_1976, _1976, 1.0), 0.0, 1.0);
    float _2000 = fast::clamp(fma(dot(-_1972, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2139 = fast::normalize(_1013 + _1972);
    float _2060 = fast::clamp(dot(_2434, _1972), 0.0, 1.0);
    float3 _2177 = cross(_2434, _2139);
    float _2180 = fast::clamp(dot(_2434, _2139), 0.0, 1.0) * params.facet_alpha;
    float _2189 = params.facet_alpha / fma(_2180, _2180, dot(_2177, _2177));
    float _2235 = 1.0 - fast::clamp(dot(_1972, _2139), 0.0, 1.0);
    float _2238 = _2235 * _2235;
    out.fragColor = float4(_1929 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2238 * _2238) * _2235))) * (((_2189 * _2189) * 0.3183098733425140380859375) * (0.5 / fma(_2060, _1873, _1455 * sqrt(fma(_2060 * _2060, _1869, _1863))))), _1539, _1752) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1981 * _1981) / fast::max(_1967, 9.9999997473787516355514526367188e-05)) * _2000) * _2000)) * _2060), float3(65504.0)), 1.0);
    return out;
}

