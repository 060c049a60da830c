// The sun's cascaded shadow map, fitted on the CPU (docs/shadows.md, "Cascade fitting"): where
// each cascade's orthographic view lies, where it goes in the atlas, and the ShadowUniforms the
// receiver shaders read. No graphics API: the shadow pass of either backend draws the casters with
// each cascade's viewProjection into its viewport, and binds the uniforms to the receivers.
//
// Splits: the practical split scheme (Zhang et al., "Parallel-Split Shadow Maps for Large-scale
// Virtual Environments", 2006): split i of N between the camera's near plane n and the shadow
// distance D is λ·n·(D/n)^(i/N) + (1 − λ)·(n + (D − n)·i/N), λ = shadows.splitLambda.
// Stability (Valient, "Stable Rendering of Cascaded Shadow Maps", ShaderX6, 2008): each cascade
// bounds the sphere around its slice of the view frustum, whose radius depends only on the
// slice's depths and the field of view (not on where the camera looks), and its centre is snapped
// to whole texels of the sun's frame, which does not turn with the camera: moving the camera moves
// the cascade's texel grid by whole texels, so the shadow does not shimmer.
//
// Atlas layout: one cascade takes the whole atlas; two to four take the squares of a 2×2 grid of
// half-size squares, cascade i at column i % 2, row i / 2 (squares past the last cascade unused);
// spot lights that cast take the cells after them (spot_shadow.h, shadowAtlasCell).
// Texel (column, row) of the atlas is its texture coordinate ((column + ½) / size, (row + ½) / size)
// and row `row` of its memory: in GL window y = row; the Vulkan shadow pass must keep GL's clip y
// (convert z to [0, 1] only, no y flip) so that its rows land where GL's do.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "facet/abi/shader_abi.h"
#include "facet/scene/scene.h"

namespace facet::runtime {

struct CasterBounds {
  glm::dvec3 center;
  double radius;  // a caster's world bounding sphere
};

struct SunCascade {
  // World → GL clip (x, y, z in [−1, 1]) of the cascade's orthographic view; the viewport below is
  // not folded in. Window depth (z + 1) / 2 is 0 nearest the sun. It has the camera's handedness
  // (a world triangle counter-clockwise seen from the sun is counter-clockwise in the window).
  glm::dmat4 viewProjection;
  std::array<uint32_t, 4> viewport;  // x, y, width, height in atlas texels (layout above)
  glm::dvec3 center;                 // the sphere around the cascade's slice of the view frustum
  double radius;
  double texelSize;            // metres per atlas texel, across the sun's rays
  double depthRange;           // metres along the rays spanned by depth 0..1 (to turn texel biases into depth)
  double splitNear, splitFar;  // camera view depths the cascade covers
};

struct SunShadowFit {
  std::vector<SunCascade> cascades;  // scene.shadows.cascades of them; none without a sun
  abi::ShadowUniforms uniforms{};    // exactly what the receiver shaders read
};

// The cascades of the scene's sun and camera. `casters` are the bounding spheres of the objects
// drawn into the atlas: each cascade's depth range reaches towards the sun to hold every caster
// that can shadow it (casterInCascade), cameras' view or not.
SunShadowFit fitSunShadow(const Scene& scene, std::span<const CasterBounds> casters);

// Whether a caster can throw a shadow into the cascade: its sphere, swept down-sun along the
// sun's rays (`sunDirection`, the direction the light travels), comes within half the cascade's
// square (texelSize × viewport width / 2: the slice's sphere, the snap and the guard band that
// normal offsets and filters read) of the cascade's centre. A caster it rejects cannot change any
// texel a receiver of the cascade reads.
// Texels of guard band a view keeps beyond what its receivers can see, in a square of `size`
// texels: min(ceil(normalBias) + 2, size / 4).
double shadowGuardTexels(double normalBias, uint32_t size);

bool casterInCascade(const SunCascade& cascade, const CasterBounds& caster, const glm::dvec3& sunDirection);

}  // namespace facet::runtime
