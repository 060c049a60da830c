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
    float3 _1028 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1163 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1166 = facet_material_albedo.sample(facet_material_albedoSmplr, _1163);
    float4 _1176 = facet_material_relief.sample(facet_material_reliefSmplr, _1163);
    float3 _1180 = (_1176.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1186 = fract(_1163 * 4.0);
    float _1188 = _1186.x;
    float _1195 = _1186.y;
    float3 _2466;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2466 = fast::normalize(in.v_normal);
            break;
        }
        _2466 = fast::normalize(((in.v_tangent.xyz * _1180.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1180.y)) + (in.v_normal * _1180.z));
        break;
    } while(false);
    float3 _1380 = fast::clamp(_1166.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1389 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1188, 1.0 - _1188), fast::min(_1195, 1.0 - _1195)))), 0.0, 1.0);
    float _1470 = fast::max(dot(_2466, _1028), 9.9999997473787516355514526367188e-05);
    float4 _1535 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1470, params.facet_perceptualRoughness), level(0.0));
    float3 _1554 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1535.y) - 1.0));
    float3 _1637 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1640 = dot(_1637, _1637);
    float3 _1645 = _1637 * rsqrt(fast::max(_1640, 9.9999999392252902907785028219223e-09));
    float _1649 = _1640 * float(frame.punctualLights[0].positionFalloff.w);
    float _1654 = fast::clamp(fma(-_1649, _1649, 1.0), 0.0, 1.0);
    float _1673 = fast::clamp(fma(dot(-_1645, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1812 = fast::normalize(_1028 + _1645);
    float _1733 = fast::clamp(dot(_2466, _1645), 0.0, 1.0);
    float _1850 = 4096.0 * params.facet_alpha;
    float4 _1874 = float4(cross(_2466, _1812), params.facet_alpha * fast::clamp(dot(_2466, _1812), 0.0, 1.0)) * 64.0;
    float _1856 = _1850 / dot(_1874, _1874);
    float _1885 = params.facet_alpha * params.facet_alpha;
    float _1891 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1895 = sqrt(fma(_1470 * _1470, _1891, _1885));
    float _1918 = 1.0 - fast::clamp(dot(_1645, _1812), 0.0, 1.0);
    float _1921 = _1918 * _1918;
    float3 _1764 = _1380 * 0.3183098733425140380859375;
    float3 _1951 = fma(_1380 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2466.y)) + (frame.sh[2].xyz * _2466.z)) + (frame.sh[3].xyz * _2466.x)) + (((((frame.sh[4].xyz * (_2466.x * _2466.y)) + (frame.sh[5].xyz * (_2466.y * _2466.z))) + (frame.sh[6].xyz * fma(3.0 * _2466.z, _2466.z, -1.0))) + (frame.sh[7].xyz * (_2466.x * _2466.z))) + (frame.sh[8].xyz * fma(_2466.x, _2466.x, -(_2466.y * _2466.y)))), float3(0.0)), fast::max(float3(_1389), ((((((_1380 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1389) + ((_1380 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1389) + ((_1380 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1389), (facet_environment.sample(facet_environmentSmplr, reflect(-_1028, _2466), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1535.xxx, _1535.yyy, float3(0.039999999105930328369140625)) * _1554)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1470 + _1389)) - 1.0) + _1389, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1921 * _1921) * _1918))) * (((_1856 * _1856) * 0.3183098733425140380859375) * (0.5 / fma(_1733, _1895, _1470 * sqrt(fma(_1733 * _1733, _1891, _1885))))), _1554, _1764) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1654 * _1654) / fast::max(_1640, 9.9999997473787516355514526367188e-05)) * _1673) * _1673)) * _1733), float3(65504.0));
    float3 _1986 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1989 = dot(_1986, _1986);
    float3 _1994 = _1986 * rsqrt(fast::max(_1989, 9.9999999392252902907785028219223e-09));
    float _1998 = _1989 * float(frame.punctualLights[1].positionFalloff.w);
    float _2003 = fast::clamp(fma(-_1998, _1998, 1.0), 0.0, 1.0);
    float _2022 = fast::clamp(fma(dot(-_1994, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2161 = fast::normalize(_1028 + _1994);
    float _2082 = fast::clamp(dot(_2466, _1994), 0.0, 1.0);
    float4 _2223 = float4(cross(_2466, _2161), params.facet_alpha * fast::clamp(dot(_2466, _2161), 0.0, 1.0)) * 64.0;
    float _2205 = _1850 / dot(_2223, _2223);
    float _2267 = 1.0 - fast::clamp(dot(_1994, _2161), 0.0, 1.0);
    float _2270 = _2267 * _2267;
    out.fragColor = float4(_1951 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2270 * _2270) * _2267))) * (((_2205 * _2205) * 0.3183098733425140380859375) * (0.5 / fma(_2082, _1895, _1470 * sqrt(fma(_2082 * _2082, _1891, _1885))))), _1554, _1764) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2003 * _2003) / fast::max(_1989, 9.9999997473787516355514526367188e-05)) * _2022) * _2022)) * _2082), float3(65504.0)), 1.0);
    return out;
}

