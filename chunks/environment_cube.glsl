// The prefiltered environment facet_environment: an RGBA16F cube map (docs/ibl.md, "Conventions";
// facet::ibl::CubeImage on the CPU), sampled with a world direction as it is: the texture unit
// selects the face and the texel (Vulkan's and GLES 3.0's cube map table), and filters across
// faces (seamless in both APIs), so the lookup costs the shader no arithmetic, where an octahedral
// map's fold (one reciprocal, abs, selects) costs 0.11 Mali-G57 cycles per lookup and an equirect
// atan + acos 0.34 (docs/platform-facts.md, "The environment lookup").
// Level m holds perceptual roughness 1 − √(1 − m / (levels − 1)) (facet::ibl::prefilterLevelRoughness),
// FACET_ENVIRONMENT_LEVELS set by the assembler; every read passes an explicit lod, so no
// derivative is taken (none is needed, and the face changes under a pixel's footprint at edges).
// Precision: the direction is the tier's (mediump on mobile tiers) and need not be unit length
// (the face coordinates are ratios sc/|m|); binary16's 2^-11 relative error moves a lookup by
// about 2^-10 of a face, 1/16 of a texel of the 64² level 0. With true half arithmetic the
// direction reaches the sampler as 32-bit (compiler::lowerHalfImageOperands).
#define ENVIRONMENT_MAX_LOD float(FACET_ENVIRONMENT_LEVELS - 1)
