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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_ripples [[texture(8)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_ripplesSmplr [[sampler(8)]])
{
    main0_out out = {};
    float3 _767 = fast::normalize(in.v_toEye);
    float4 _881 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    float3 _885 = (_881.xyz * 2.007874011993408203125) - float3(1.007874011993408203125);
    float3 _1556;
    do
    {
        if (dot(in.v_tangent.xyz, in.v_tangent.xyz) == 0.0)
        {
            _1556 = fast::normalize(in.v_normal);
            break;
        }
        _1556 = fast::normalize(((in.v_tangent.xyz * _885.x) + ((cross(in.v_normal, in.v_tangent.xyz) * in.v_tangent.w) * _885.y)) + (in.v_normal * _885.z));
        break;
    } while(false);
    float _934 = fast::clamp(params.roughness, 0.08900000154972076416015625, 1.0);
    float3 _943 = dfdx(_1556);
    float3 _945 = dfdy(_1556);
    float _956 = _934 * _934;
    float _1156 = fast::clamp(sqrt(sqrt(fast::min(fma(_956, _956, fast::min((dot(_943, _943) + dot(_945, _945)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0))), 0.08900000154972076416015625, 1.0);
    float _1123 = fast::max(dot(_1556, _767), 9.9999997473787516355514526367188e-05);
    float4 _1163 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1123, _1156), level(0.0));
    float3 _1182 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1163.y) - 1.0));
    float _1304 = _1156 * _1156;
    float3 _1315 = fast::normalize(_767 + frame.lightDirection.xyz);
    float _1249 = fast::clamp(dot(_1556, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1353 = cross(_1556, _1315);
    float _1356 = fast::clamp(dot(_1556, _1315), 0.0, 1.0) * _1304;
    float _1365 = _1304 / fma(_1356, _1356, dot(_1353, _1353));
    float _1378 = _1304 * _1304;
    float _1384 = fma(-_1304, _1304, 1.0);
    float _1411 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1315), 0.0, 1.0);
    float _1414 = _1411 * _1411;
    float3 _1436 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1556.y)) + (frame.sh[2].xyz * _1556.z)) + (frame.sh[3].xyz * _1556.x)) + (((((frame.sh[4].xyz * (_1556.x * _1556.y)) + (frame.sh[5].xyz * (_1556.y * _1556.z))) + (frame.sh[6].xyz * fma(3.0 * _1556.z, _1556.z, -1.0))) + (frame.sh[7].xyz * (_1556.x * _1556.z))) + (frame.sh[8].xyz * fma(_1556.x, _1556.x, -(_1556.y * _1556.y)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_767, _1556), level(_1156 * 4.0)).xyz * (mix(_1163.xxx, _1163.yyy, float3(params.facet_f0)) * _1182)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1414 * _1414) * _1411))) * (((_1365 * _1365) * 0.3183098733425140380859375) * (0.5 / fma(_1249, sqrt(fma(_1123 * _1123, _1384, _1378)), _1123 * sqrt(fma(_1249 * _1249, _1384, _1378))))), _1182, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1249), float3(65504.0));
    out.fragColor = float4(_1436, 1.0);
    return out;
}

