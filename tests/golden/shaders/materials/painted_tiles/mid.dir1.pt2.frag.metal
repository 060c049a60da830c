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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texture2d<float> facet_material_albedo [[texture(8)]], texture2d<float> facet_material_relief [[texture(9)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_material_albedoSmplr [[sampler(8)]], sampler facet_material_reliefSmplr [[sampler(9)]])
{
    main0_out out = {};
    float3 _741 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float2 _912 = in.v_uv0 * float2(half2(half(2.0) * half(params.tiling), half(params.tiling)));
    float4 _915 = facet_material_albedo.sample(facet_material_albedoSmplr, _912);
    float4 _925 = facet_material_relief.sample(facet_material_reliefSmplr, _912);
    half3 _929 = (half4(_925).xyz * half(2.007874011993408203125)) - half3(float3(1.007874011993408203125));
    float2 _935 = fract(_912 * 4.0);
    float _937 = _935.x;
    float _944 = _935.y;
    half3 _2055;
    do
    {
        half3 _969 = half4(in.v_tangent).xyz;
        if (float(dot(_969, _969)) == 0.0)
        {
            _2055 = normalize(half3(in.v_normal));
            break;
        }
        _2055 = normalize(((_969 * _929.x) + ((cross(half3(in.v_normal), _969) * half(in.v_tangent.w)) * _929.y)) + (half3(in.v_normal) * _929.z));
        break;
    } while(false);
    half3 _1012 = clamp(half4(_915).xyz, half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1018 = clamp(half(mix(0.4000000059604644775390625, 1.0, smoothstep(0.0, 0.3499999940395355224609375, fast::min(fast::min(_937, 1.0 - _937), fast::min(_944, 1.0 - _944))))), half(0.0), half(1.0));
    half _1065 = max(dot(_2055, half3(_741)), half(9.9999997473787516355514526367188e-05));
    float4 _1130 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1065, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1149 = half3(float3(1.0)) + (half3(float3(0.039999999105930328369140625)) * ((half(1.0) / half4(_1130).y) - half(1.0)));
    float4 _1156 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_741), _2055)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _794 = half4(frame.lightDirection).xyz;
    half3 _1293 = normalize(half3(_741) + _794);
    half _1220 = clamp(dot(_2055, _794), half(0.0), half(1.0));
    half3 _1320 = cross(_2055, _1293);
    half _1323 = clamp(dot(_2055, _1293), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1340 = max(mix((half(2.0) * _1220) * _1065, _1220 + _1065, half(params.facet_alpha)), half(0.000244140625));
    half _1342 = half(1024.0) * half(params.facet_alpha);
    half _1347 = _1342 / (fma(_1323, _1323, dot(_1320, _1320)) * (half(6433.98193359375) * _1340));
    float3 _1395 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1398 = dot(_1395, _1395);
    float3 _1403 = _1395 * rsqrt(fast::max(_1398, 9.9999999392252902907785028219223e-09));
    float _1407 = _1398 * float(frame.punctualLights[0].positionFalloff.w);
    float _1412 = fast::clamp(fma(-_1407, _1407, 1.0), 0.0, 1.0);
    float _1431 = fast::clamp(fma(dot(-_1403, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1565 = normalize(half3(_741) + half3(_1403));
    half _1492 = clamp(dot(_2055, half3(_1403)), half(0.0), half(1.0));
    half3 _1592 = cross(_2055, _1565);
    half _1595 = clamp(dot(_2055, _1565), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1612 = max(mix((half(2.0) * _1492) * _1065, _1492 + _1065, half(params.facet_alpha)), half(0.000244140625));
    half _1619 = _1342 / (fma(_1595, _1595, dot(_1592, _1592)) * (half(6433.98193359375) * _1612));
    float3 _1667 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1670 = dot(_1667, _1667);
    float3 _1675 = _1667 * rsqrt(fast::max(_1670, 9.9999999392252902907785028219223e-09));
    float _1679 = _1670 * float(frame.punctualLights[1].positionFalloff.w);
    float _1684 = fast::clamp(fma(-_1679, _1679, 1.0), 0.0, 1.0);
    float _1703 = fast::clamp(fma(dot(-_1675, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1837 = normalize(half3(_741) + half3(_1675));
    half _1764 = clamp(dot(_2055, half3(_1675)), half(0.0), half(1.0));
    half3 _1864 = cross(_2055, _1837);
    half _1867 = clamp(dot(_2055, _1837), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1884 = max(mix((half(2.0) * _1764) * _1065, _1764 + _1065, half(params.facet_alpha)), half(0.000244140625));
    half _1891 = _1342 / (fma(_1867, _1867, dot(_1864, _1864)) * (half(6433.98193359375) * _1884));
    half3 _1903 = (((fma(_1012, half3(in.v_directDiffuse), (_1012 * half3(in.v_diffuseLight)) * _1018) + ((half4(_1156).xyz * (mix(half4(_1130).xxx, half4(_1130).yyy, half3(float3(0.039999999105930328369140625))) * _1149)) * _1018)) + min(((half3(float3(0.039999999105930328369140625)) * min(_1347 * (_1347 * (half(6.283185482025146484375) * _1340)), half(65504.0))) * _1149) * (half4(frame.lightColor).xyz * _1220), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1619 * (_1619 * (half(6.283185482025146484375) * _1612)), half(65504.0))) * _1149) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1412) * half(_1412)) / fast::max(_1398, 9.9999997473787516355514526367188e-05)) * half(_1431)) * half(_1431)), float3(65504.0))) * _1492), half3(float3(65504.0)))) + min(((half3(float3(0.039999999105930328369140625)) * min(_1891 * (_1891 * (half(6.283185482025146484375) * _1884)), half(65504.0))) * _1149) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1684) * half(_1684)) / fast::max(_1670, 9.9999997473787516355514526367188e-05)) * half(_1703)) * half(_1703)), float3(65504.0))) * _1764), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1903, half(1.0)));
    return out;
}

