#include "math.glsl"

// Equirect coordinates of a world direction, the contract of facet_ibl (docs/ibl.md,
// "Conventions"; facet::ibl::equirectCoordinates on the CPU):
//   s = atan(d.z, d.x) / 2π,   t = acos(d.y) / π      (row 0 = zenith, +y up)
// s runs over [−½, ½]: the environment's sampler repeats in s (and clamps in t), so the wrap at
// the −x seam costs no fract(), and bilinear filtering blends across it.
// Precision: computed in highp whatever the tier. acos is steep at ±1: the largest fp16 value
// below 1 is 1 − 2^-11, whose acos is 0.031 rad, 0.64 rows of a 64-row map, so a mediump acos
// cannot resolve the rows next to the poles; atan/acos are also the functions mobile GPUs
// implement most loosely in fp16. Two highp transcendentals per lookup, usually the same rate
// as their fp16 forms. The direction itself may be mediump (a reflected unit vector): its
// rounding moves the lookup by about one fp16 step of angle, well under a texel. At the poles
// (d.x = d.z = 0) atan is undefined; the 1e-30 (a normal fp32 number) keeps it finite, and
// every s of the pole row holds the same direction anyway.
highp vec2 equirect_uv(highp vec3 d) {
    return vec2(atan(d.z, d.x + 1e-30) * (0.5 * INV_PI), acos(clamp(d.y, -1.0, 1.0)) * INV_PI);
}

// The prefiltered environment's last level: level m holds perceptual roughness m / (levels − 1)
// (facet::ibl::prefilterLevelRoughness), FACET_ENVIRONMENT_LEVELS set by the assembler.
#define ENVIRONMENT_MAX_LOD float(FACET_ENVIRONMENT_LEVELS - 1)
