// Spot lights' shadows, fitted on the CPU (docs/shadows.md, "Spot shadows"): each casting spot
// light a perspective view from its position along its axis, fitted to its cone, in a rectangle of
// the same depth atlas as the sun's cascades. No graphics API: the shadow pass of either backend
// draws the casters with the view's viewProjection into its viewport, as it draws a cascade.
//
// Atlas layout, cascades and spot views together: V views take the cells of a k × k grid, k the
// smallest of 1, 2, 3 with k² ≥ V, each cell ⌊atlas / k⌋ texels square, view i at column i mod k,
// row ⌊i / k⌋, the sun's cascades first and then the spots in light-slot order. The sun alone keeps
// the layout sun_shadow.h gives (one cascade the whole atlas, two to four a 2×2 grid); four
// cascades and a spot take a 3×3 grid.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "facet/runtime/sun_shadow.h"
#include "facet/scene/scene.h"

namespace facet::runtime {

// Cell `index` of an atlas of `atlasSize` texels holding `views` views (layout above): x, y,
// width, height in atlas texels.
std::array<uint32_t, 4> shadowAtlasCell(uint32_t atlasSize, uint32_t views, uint32_t index);

struct SpotShadow {
  size_t light = 0;  // index into Scene::lights
  // World → GL clip of the perspective view from the light along its axis (x, y, z in [−1, 1]);
  // the viewport below is not folded in. It has the camera's handedness (a triangle
  // counter-clockwise seen from the light is counter-clockwise in the window), and window depth
  // (z + 1) / 2 is 0 at nearPlane and 1 at farPlane.
  glm::dmat4 viewProjection{1.0};
  std::array<uint32_t, 4> viewport{};  // x, y, width, height in atlas texels
  glm::dvec3 position{0.0};
  glm::dvec3 axis{0, -1, 0};           // unit, the direction the light travels
  double halfAngle = 0;                // radians: the view's half field of view, the cone and the guard band
  double nearPlane = 0, farPlane = 0;  // metres along the axis
  double texelPerMetre = 0;            // a texel's width at 1 m along the axis, metres (× distance elsewhere)
  // World → atlas (u·w, v·w, depth·w, w): viewProjection with the viewport and window depth folded
  // in, what a receiver multiplies its position by before dividing by w (in highp).
  glm::dmat4 atlasFromWorld{1.0};
};

// The view of `scene.lights[light]` (a spot light) in `viewport`, of an atlas of `atlasSize`
// texels: field of view twice the outer angle widened by a guard band of normalBias + 2 texels on
// each side (the receiver's normal offset and the 3×3 tent read that far beyond the cone), near
// plane range / 100 and far plane the light's range.
SpotShadow fitSpotShadow(const Scene& scene, size_t light, const std::array<uint32_t, 4>& viewport);

// Whether a caster's bounding sphere meets the view's cone (half-angle halfAngle, from the light
// to farPlane): one it rejects lies outside every ray of the light a receiver's lookup can read.
bool casterInSpotCone(const SpotShadow& spot, const CasterBounds& caster);

// The window depth a constant depth bias of `texels` texels' width along the ray is, for a surface
// at the middle of the light's range (perspective depth is not linear: the same constant is
// (z / zMid)² as many metres at distance z).
double spotDepthBias(const SpotShadow& spot, double texels);
// The vertex-stage slope bias's constant (ShadowCascadeDesc::vertexSlopeBias): the window depth of
// `texels` texels' width along the axis at distance z, times w = z, the same at every distance.
double spotVertexSlopeBias(const SpotShadow& spot, double texels);

}  // namespace facet::runtime
