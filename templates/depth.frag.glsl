// Shadow pass, fragment stage: the depth-only program of a material that casts (docs/shadows.md).
// Opaque: nothing (the rasterizer writes the depth; GLSL ES 3.00 still needs a fragment stage).
// Masked: the forward pass's alpha test (chunks/output_blending.glsl, without MSAA's alpha to
// coverage: the atlas has one sample), on the surface program reduced to what alpha reads, at the
// tier's precision like the forward variant's, so a cut-out casts the shape it shows.
#if defined(FACET_BLENDING_MASKED)
#include "math.glsl"
#include "precision.glsl"
#include "facet:material"
#endif

void main() {
#if defined(FACET_BLENDING_MASKED)
    MaterialInputs material = material_defaults();
    evaluate_surface(material);
    if (material.alpha < FACET_ALPHA_CUTOFF) discard;
#endif
}
