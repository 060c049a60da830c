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
    float3 _1031 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _1187 = in.v_uv0 * float2(2.0 * params.tiling, params.tiling);
    float4 _1190 = facet_material_albedo.sample(facet_material_albedoSmplr, _1187);
    float4 _1200 = facet_material_relief.sample(facet_material_reliefSmplr, _1187);
    float3 _1204 = (_1200.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float2 _1210 = fract(_1187 * 4.0);
    float _1212 = _1210.x;
    float _1219 = _1210.y;
    float3 _2772;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _2772 = fast::normalize(in.v_normal);
            break;
        }
        _2772 = fast::normalize(((in.v_tangent.xyz * _1204.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _1204.y)) + (in.v_normal * _1204.z));
        break;
    } while(false);
    float3 _1404 = fast::clamp(_1190.xyz, float3(0.0), float3(1.0)) * 1.0;
    float _1413 = fast::clamp(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_1212, 1.0 - _1212), fast::min(_1219, 1.0 - _1219)))), 0.0, 1.0);
    float _1494 = fast::max(dot(_2772, _1031), 9.9999997473787516355514526367188e-05);
    float4 _1559 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1494, params.facet_perceptualRoughness), level(0.0));
    float3 _1578 = float3(1.0) + (float3(0.039999999105930328369140625) * ((1.0 / _1559.y) - 1.0));
    float3 _1759 = fast::normalize(_1031 + frame.lightDirection.xyz);
    float _1680 = fast::clamp(dot(_2772, frame.lightDirection.xyz), 0.0, 1.0);
    float _1797 = 4096.0 * params.facet_alpha;
    float4 _1821 = float4(cross(_2772, _1759), params.facet_alpha * fast::clamp(dot(_2772, _1759), 0.0, 1.0)) * 64.0;
    float _1803 = _1797 / dot(_1821, _1821);
    float _1832 = params.facet_alpha * params.facet_alpha;
    float _1838 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1842 = sqrt(fma(_1494 * _1494, _1838, _1832));
    float _1865 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1759), 0.0, 1.0);
    float _1868 = _1865 * _1865;
    float3 _1711 = _1404 * 0.3183098733425140380859375;
    float3 _1898 = fma(_1404 * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _2772.y)) + (frame.sh[2].xyz * _2772.z)) + (frame.sh[3].xyz * _2772.x)) + (((((frame.sh[4].xyz * (_2772.x * _2772.y)) + (frame.sh[5].xyz * (_2772.y * _2772.z))) + (frame.sh[6].xyz * fma(3.0 * _2772.z, _2772.z, -1.0))) + (frame.sh[7].xyz * (_2772.x * _2772.z))) + (frame.sh[8].xyz * fma(_2772.x, _2772.x, -(_2772.y * _2772.y)))), float3(0.0)), fast::max(float3(_1413), ((((((_1404 * 2.040400028228759765625) - float3(0.3323999941349029541015625)) * _1413) + ((_1404 * (-4.79510021209716796875)) + float3(0.6417000293731689453125))) * _1413) + ((_1404 * 2.755199909210205078125) + float3(0.69029998779296875))) * _1413), (facet_environment.sample(facet_environmentSmplr, reflect(-_1031, _2772), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1559.xxx, _1559.yyy, float3(0.039999999105930328369140625)) * _1578)) * fast::clamp((exp2(exp2(fma(-16.0, params.facet_perceptualRoughness * params.facet_perceptualRoughness, -1.0)) * log2(_1494 + _1413)) - 1.0) + _1413, 0.0, 1.0)) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_1868 * _1868) * _1865))) * (((_1803 * _1803) * 0.3183098733425140380859375) * (0.5 / fma(_1680, _1842, _1494 * sqrt(fma(_1680 * _1680, _1838, _1832))))), _1578, _1711) * (frame.lightColor.xyz * _1680), float3(65504.0));
    float3 _1933 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1936 = dot(_1933, _1933);
    float3 _1941 = _1933 * rsqrt(fast::max(_1936, 9.9999999392252902907785028219223e-09));
    float _1945 = _1936 * float(frame.punctualLights[0].positionFalloff.w);
    float _1950 = fast::clamp(fma(-_1945, _1945, 1.0), 0.0, 1.0);
    float _1969 = fast::clamp(fma(dot(-_1941, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2108 = fast::normalize(_1031 + _1941);
    float _2029 = fast::clamp(dot(_2772, _1941), 0.0, 1.0);
    float4 _2170 = float4(cross(_2772, _2108), params.facet_alpha * fast::clamp(dot(_2772, _2108), 0.0, 1.0)) * 64.0;
    float _2152 = _1797 / dot(_2170, _2170);
    float _2214 = 1.0 - fast::clamp(dot(_1941, _2108), 0.0, 1.0);
    float _2217 = _2214 * _2214;
    float3 _2282 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2285 = dot(_2282, _2282);
    float3 _2290 = _2282 * rsqrt(fast::max(_2285, 9.9999999392252902907785028219223e-09));
    float _2294 = _2285 * float(frame.punctualLights[1].positionFalloff.w);
    float _2299 = fast::clamp(fma(-_2294, _2294, 1.0), 0.0, 1.0);
    float _2318 = fast::clamp(fma(dot(-_2290, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2457 = fast::normalize(_1031 + _2290);
    float _2378 = fast::clamp(dot(_2772, _2290), 0.0, 1.0);
    float4 _2519 = float4(cross(_2772, _2457), params.facet_alpha * fast::clamp(dot(_2772, _2457), 0.0, 1.0)) * 64.0;
    float _2501 = _1797 / dot(_2519, _2519);
    float _2563 = 1.0 - fast::clamp(dot(_2290, _2457), 0.0, 1.0);
    float _2566 = _2563 * _2563;
    float3 _2596 = (_1898 + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2217 * _2217) * _2214))) * (((_2152 * _2152) * 0.3183098733425140380859375) * (0.5 / fma(_2029, _1842, _1494 * sqrt(fma(_2029 * _2029, _1838, _1832))))), _1578, _1711) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1950 * _1950) / fast::max(_1936, 9.9999997473787516355514526367188e-05)) * _1969) * _1969)) * _2029), float3(65504.0))) + fast::min(fma((float3(0.039999999105930328369140625) + (float3(0.959999978542327880859375) * ((_2566 * _2566) * _2563))) * (((_2501 * _2501) * 0.3183098733425140380859375) * (0.5 / fma(_2378, _1842, _1494 * sqrt(fma(_2378 * _2378, _1838, _1832))))), _1578, _1711) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2299 * _2299) / fast::max(_2285, 9.9999997473787516355514526367188e-05)) * _2318) * _2318)) * _2378), float3(65504.0));
    out.fragColor = float4(_2596, 1.0);
    return out;
}

