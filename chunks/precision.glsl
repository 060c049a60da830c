// Precision policy for mediump shading (binary16 on mobile GPUs: largest finite 65504, smallest
// normal 2^-14 ≈ 6.1e-5, 11 significant bits). Sources: Filament mobile talk and Filament's
// "Physically Based Rendering" §4.4 (fp16 considerations); Zioma 2015 on mobile precision.
//
// Chunks carry no precision qualifiers: the tier's default float precision applies (mediump for
// the mobile tiers, highp for `reference`), so one chunk serves both. Values that must stay
// highp whatever the tier (positions, UVs) say so where they are declared.
//
// Contract with the runtime: lights arrive pre-exposed (intensity × camera exposure), so lit
// values are O(1) and a 110 000 lux sun does not overflow 65504.

#define MEDIUMP_FLT_MAX 65504.0
// Clamps a non-negative value that may overflow fp16 (D and V peaks) to the largest finite one,
// so a highlight saturates instead of turning into +inf and then NaN in later products.
// The highp tier (`reference`, FACET_PRECISION_HIGHP) is the ground truth: its values do not
// overflow at 65504, and clamping there would lose real energy (the grazing glint of a smooth
// surface has D·V > 65504), so the clamp is Filament's: only where shading runs at mediump.
#if defined(FACET_PRECISION_HIGHP)
#define saturateMediump(x) (x)
#else
#define saturateMediump(x) min(x, MEDIUMP_FLT_MAX)
#endif

// D divides by terms of α² = r⁴ (r = perceptual roughness). Keeping r⁴ ≥ 2^-14, the smallest
// normal fp16 value, needs r ≥ 2^(-14/4) ≈ 0.0884; 0.089 is Filament's mobile floor
// (0.089⁴ = 6.27e-5 ≥ 6.10e-5).
const float MIN_PERCEPTUAL_ROUGHNESS = 0.089;

// n·v is clamped away from 0 before it reaches V's denominators: at grazing angles the
// interpolated normal can face away from the eye. 1e-4 is above fp16's subnormal range
// (2^-14 ≈ 6.1e-5), so it stays a normal number and 1/NoV-like terms stay finite.
const float MIN_N_DOT_V = 1e-4;
