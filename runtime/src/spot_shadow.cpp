#include "facet/runtime/spot_shadow.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace facet::runtime {

std::array<uint32_t, 4> shadowAtlasCell(uint32_t atlasSize, uint32_t views, uint32_t index) {
  const uint32_t k = views <= 1 ? 1 : views <= 4 ? 2 : 3;
  const uint32_t size = atlasSize / k;
  return {(index % k) * size, (index / k) * size, size, size};
}

SpotShadow fitSpotShadow(const Scene& scene, size_t light, const std::array<uint32_t, 4>& viewport) {
  const PunctualLight& l = scene.lights.at(light);
  SpotShadow s;
  s.light = light;
  s.viewport = viewport;
  s.position = l.position;
  s.axis = glm::normalize(l.direction);
  const double size = viewport[2];
  // The cone's edge lands guard texels inside the cell's edge: tan(half) · (size/2 − guard) =
  // tan(outer) · size/2.
  const double guard = shadowGuardTexels(scene.shadows.normalBias, viewport[2]);
  const double outer = glm::radians(std::min(l.outerAngleDegrees, kMaxShadowSpotAngleDegrees));
  s.halfAngle = std::atan(std::tan(outer) * (size / 2) / (size / 2 - guard));
  // Near: a hundredth of the range, which keeps a D16 depth's step below range × 0.0015 at the
  // range's end (a step there is z² / (near · 65536) for far ≫ near); a caster nearer the light
  // than that is clipped. Far: the range, where the light has faded to nothing.
  s.farPlane = l.range;
  s.nearPlane = l.range / 100;
  // The light's frame: world up unless the axis is within 2.6° of vertical, where the cross
  // product that lookAt takes loses its precision (as the sun's frame, sun_shadow.cpp).
  const glm::dvec3 up = std::abs(s.axis.y) < 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  const glm::dmat4 view = glm::lookAt(s.position, s.position + s.axis, up);
  s.viewProjection = glm::perspective(2 * s.halfAngle, 1.0, s.nearPlane, s.farPlane) * view;
  s.texelPerMetre = 2 * std::tan(s.halfAngle) / size;
  // Clip → (u·w, v·w, depth·w, w): u = (x0 + (X / W + 1) · size / 2) / atlas, depth = (Z / W + 1) / 2.
  const double atlas = scene.shadows.atlasSize;
  glm::dmat4 toAtlas(0.0);
  toAtlas[0][0] = size / (2 * atlas);
  toAtlas[1][1] = size / (2 * atlas);
  toAtlas[2][2] = 0.5;
  toAtlas[3] = glm::dvec4((viewport[0] + size / 2) / atlas, (viewport[1] + size / 2) / atlas, 0.5, 1);
  s.atlasFromWorld = toAtlas * s.viewProjection;
  return s;
}

bool casterInSpotCone(const SpotShadow& spot, const CasterBounds& caster) {
  // Wronski, "Cull that cone! Improved cone/spotlight visibility tests for tiled and clustered
  // lighting" (2017): the sphere's centre at distance `along` on the axis and `across` from it
  // lies cos(θ)·across − sin(θ)·along from the cone's side; it is out when that exceeds its radius,
  // or when it lies wholly behind the light or past the far plane.
  const glm::dvec3 v = caster.center - spot.position;
  const double along = glm::dot(v, spot.axis);
  const double across = std::sqrt(std::max(0.0, glm::dot(v, v) - along * along));
  const double fromSide = std::cos(spot.halfAngle) * across - std::sin(spot.halfAngle) * along;
  return fromSide <= caster.radius && along >= -caster.radius && along <= spot.farPlane + caster.radius;
}

double spotDepthBias(const SpotShadow& spot, double texels) {
  // Window depth d(z) = f / (f − n) · (1 − n / z), d'(z) = f·n / ((f − n)·z²); a texel at z is
  // texelPerMetre·z wide, so `texels` of them at zMid is texels·texelPerMetre·f·n / ((f − n)·zMid).
  const double n = spot.nearPlane, f = spot.farPlane, mid = (n + f) / 2;
  return texels * spot.texelPerMetre * f * n / ((f - n) * mid);
}

double spotVertexSlopeBias(const SpotShadow& spot, double texels) {
  // `texels` texels' width along the axis at distance z in window depth, as above, is
  // texels·texelPerMetre·f·n / ((f − n)·z): times w = z, a constant of the view.
  const double n = spot.nearPlane, f = spot.farPlane;
  return texels * spot.texelPerMetre * f * n / (f - n);
}

}  // namespace facet::runtime
