// Forward pass, unlit, fragment stage: the surface program's colour is the pixel's colour.
#include "math.glsl"
#include "precision.glsl"
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
#include "view_vector.glsl"
#endif
#include "facet:material"
#include "output_blending.glsl"

void main() {
    shading_normal = normalize(v_normal);
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
    shading_view = view_direction(FACET_TO_EYE);
#else
    shading_view = normalize(FACET_TO_EYE);
#endif
    MaterialInputs material = material_defaults();
    evaluate_surface(material);
    fragColor = blend_output(linear_from_shading_space(material.baseColor + material.emissive), material.alpha);
}
