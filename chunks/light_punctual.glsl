#include "precision.glsl"

// Punctual lights (point and spot), Filament's model (Filament PBR document §5.2.2):
//   E⊥(d) = I / max(d², (1 cm)²) · window(d),   window(d) = saturate(1 − (d / range)⁴)²
//   spot: E⊥ · saturate(cos θ · scale + offset)²,  scale = 1 / (cos θ_inner − cos θ_outer),
//         offset = −cos θ_outer · scale,  θ the angle between the spot axis and the light ray
// where I is the intensity in candela, pre-exposed by the CPU (precision.glsl's contract). The
// window is Karis 2013's ("Real Shading in Unreal Engine 4"): inverse-square falloff that reaches
// exactly 0 at the light's range instead of never. The 1 cm floor keeps a light touching a
// surface finite: 1/d² ≤ 10⁴, so E⊥ stays below fp16's 65504 for pre-exposed I < 6.5; brighter
// lights that close saturate at 65504 (saturateMediump) instead of overflowing to inf.
// Precision: the surface-to-light vector and d² come from highp positions (a mediump position
// 100 m from the origin has 6 cm steps), and so does the unit vector (the half vector needs it
// highp: shading_standard.glsl, half_vector); the result drops to the tier's precision. Needs: PunctualLightData (declared with the frame block).

// Illuminance on a surface facing the light, and the unit vector towards it in *l.
vec3 punctual_light_illuminance(PunctualLightData light, highp vec3 worldPosition, out highp vec3 l) {
    highp vec3 toLight = light.positionFalloff.xyz - worldPosition;
    highp float distanceSquared = dot(toLight, toLight);
    l = toLight * inversesqrt(max(distanceSquared, 1e-8));
    highp float ratio = distanceSquared * light.positionFalloff.w;  // (d / range)²
    float window = clamp(1.0 - ratio * ratio, 0.0, 1.0);
    float attenuation = window * window / max(distanceSquared, 1e-4);
    float cone = clamp(dot(-l, light.direction.xyz) * light.spotScaleOffset.x + light.spotScaleOffset.y, 0.0, 1.0);
    return saturateMediump(light.colorIntensity.rgb * (attenuation * cone * cone));
}
