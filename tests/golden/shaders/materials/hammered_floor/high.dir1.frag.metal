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
    float3 _796 = fast::normalize(in.v_toEye);
    float4 _910 = facet_material_ripples.sample(facet_material_ripplesSmplr, (in.v_uv0 * params.tiling));
    half3 _914 = (half4(_910).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    half3 _1604;
    do
    {
        half3 _927 = half4(in.v_tangent).xyz;
        if (float(dot(_927, _927)) == 0.0)
        {
            _1604 = normalize(half3(in.v_normal));
            break;
        }
        _1604 = normalize(((_927 * _914.x) + ((cross(half3(in.v_normal), _927) * half(in.v_tangent.w)) * _914.y)) + (half3(in.v_normal) * _914.z));
        break;
    } while(false);
    half _963 = clamp(half(params.roughness), half(0.08900000154972076416015625), half(1.0));
    float3 _973 = dfdx(float3(_1604));
    float3 _975 = dfdy(float3(_1604));
    half _986 = _963 * _963;
    half3 _1104 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1604.y)) + (half4(frame.sh[2]).xyz * _1604.z)) + (half4(frame.sh[3]).xyz * _1604.x)) + (((((half4(frame.sh[4]).xyz * (_1604.x * _1604.y)) + (half4(frame.sh[5]).xyz * (_1604.y * _1604.z))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1604.z, _1604.z, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1604.x * _1604.z))) + (half4(frame.sh[8]).xyz * fma(_1604.x, _1604.x, half(-float(_1604.y * _1604.y))))), half3(float3(0.0)));
    half _1187 = clamp(half(sqrt(sqrt(fast::min(fma(float(_986), float(_986), fast::min((dot(_973, _973) + dot(_975, _975)) * 0.039999999105930328369140625, 0.20000000298023223876953125)), 1.0)))), half(0.08900000154972076416015625), half(1.0));
    half _1154 = max(dot(_1604, half3(_796)), half(9.9999997473787516355514526367188e-05));
    float4 _1194 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1154, _1187)), level(0.0));
    half3 _1213 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1194).y) - half(1.0)));
    float4 _1223 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_796), _1604)), level(_1187 * (half(4.0) * (half(2.0) - _1187))));
    half _1338 = _1187 * _1187;
    float3 _1350 = fast::normalize(_796 + frame.lightDirection.xyz);
    half _1283 = clamp(dot(_1604, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1415 = half4(cross(_1604, half3(_1350)), _1338 * clamp(dot(_1604, half3(_1350)), half(0.0), half(1.0))) * half(64.0);
    half _1396 = (half(4096.0) * _1338) / dot(_1415, _1415);
    half _1426 = _1338 * _1338;
    half _1432 = fma(half(-float(_1338)), _1338, half(1.0));
    half _1460 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1350)), half(0.0), half(1.0));
    half _1463 = _1460 * _1460;
    half3 _1485 = fma(half3(float3(params.facet_diffuseColor)), _1104, half4(_1223).xyz * (mix(half4(_1194).xxx, half4(_1194).yyy, half3(float3(params.facet_f0))) * _1213)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1463 * _1463) * _1460))) * min(min((_1396 * _1396) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1283, sqrt(fma(_1154 * _1154, _1432, _1426)), _1154 * sqrt(fma(_1283 * _1283, _1432, _1426))), half(65504.0)), half(65504.0)), _1213, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1283), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1485, half(1.0)));
    return out;
}

