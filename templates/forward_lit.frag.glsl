// Forward pass, lit, fragment stage: evaluate the material's surface program, then shade with
// one directional light and a constant ambient. Writes pre-exposed linear HDR.
#include "math.glsl"
#include "precision.glsl"
#include "facet:material"
#include "brdf_ggx.glsl"
#include "diffuse_lambert.glsl"
#include "shading_standard.glsl"

void main() {
    shading_normal = normalize(v_normal);
    MaterialInputs material = material_defaults();
    evaluate_surface(material);

    // The view vector comes from highp positions; only the unit vector drops to mediump.
    mediump vec3 v = normalize(frame.cameraPosition.xyz - v_worldPosition);
    mediump vec3 l = normalize(frame.lightDirection.xyz);
    mediump vec3 color = shade_standard(material, shading_normal, v, l, frame.lightColor.rgb, frame.ambient.rgb);
    fragColor = vec4(color + material.emissive, material.alpha);
}
