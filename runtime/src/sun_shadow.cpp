#include "facet/runtime/sun_shadow.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "facet/runtime/spot_shadow.h"

namespace facet::runtime {

namespace {

// The sun's frame: rows x, y across the rays and z along them (the direction the light travels),
// through the world's origin, so that it does not move or turn with the camera (the texel grid
// that snapping locks to is this frame's). x × y = −z, as a camera's right × up points back
// towards the eye, so that the cascade's orthographic view has the camera's handedness. The
// reference for x is world up unless the sun is within 2.6° of vertical, where that cross
// product loses its precision: world z then.
glm::dmat3 sunFrame(const glm::dvec3& direction) {
  const glm::dvec3 z = glm::normalize(direction);
  const glm::dvec3 reference = std::abs(z.y) < 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  const glm::dvec3 x = glm::normalize(glm::cross(z, reference));
  const glm::dvec3 y = glm::cross(x, z);
  return glm::transpose(glm::dmat3(x, y, z));  // rows x, y, z: world → the sun's frame
}

// Split i of n: the practical split scheme (sun_shadow.h), from near to far.
double practicalSplit(double near, double far, double lambda, uint32_t i, uint32_t n) {
  const double f = double(i) / n;
  return lambda * near * std::pow(far / near, f) + (1 - lambda) * (near + (far - near) * f);
}

// The smallest sphere around the slice of a view frustum between view depths a ≤ b, whose corners
// at depth z lie z·t from the view axis (t = tan(fovY / 2)·√(1 + aspect²)). Its centre lies on the
// axis at depth c, equally far from the near and far corners: (c − a)² + a²t² = (c − b)² + b²t²
// gives c = (a + b)(1 + t²) / 2; past b the far corners alone bound the slice, c = b, radius b·t.
// Neither depends on the camera's orientation: the radius stays as the camera turns.
struct SliceSphere {
  double depth, radius;
};
SliceSphere sliceSphere(double a, double b, double t) {
  const double c = std::min((a + b) * (1 + t * t) / 2, b);
  return {c, std::sqrt((c - a) * (c - a) + a * a * t * t)};
}

void store(float* dst, const glm::dvec3& v, double w) {
  dst[0] = float(v.x);
  dst[1] = float(v.y);
  dst[2] = float(v.z);
  dst[3] = float(w);
}

}  // namespace

// Texels a cascade keeps around its sphere: the receiver's lookup moves up to normalBias texels
// along its normal (chunks/shadow_sun.glsl) and the 3×3 tent reads texels up to 2 from the
// position, which must stay inside the cascade's square and not read its neighbour's. At most a
// quarter of the square (normalBias reaches 64): past that the guard would cost more resolution
// than the few receivers at the sphere's rim that need it.
double shadowGuardTexels(double normalBias, uint32_t size) {
  return std::min(std::ceil(normalBias) + 2, double(size) / 4);
}

bool casterInCascade(const SunCascade& cascade, const CasterBounds& caster, const glm::dvec3& sunDirection) {
  // The distance from the cascade's centre to the ray the caster's centre sweeps down-sun, against
  // the reach of the cascade's square (its half-width, which holds the sphere and the guard) plus
  // the caster's radius.
  const glm::dvec3 direction = glm::normalize(sunDirection);
  const double along = std::max(0.0, glm::dot(cascade.center - caster.center, direction));
  const double distance = glm::length(cascade.center - (caster.center + along * direction));
  const double halfWidth = 0.5 * cascade.texelSize * cascade.viewport[2];
  return distance <= halfWidth + caster.radius;
}

SunShadowFit fitSunShadow(const Scene& scene, std::span<const CasterBounds> casters) {
  SunShadowFit fit;
  if (!scene.sun) return fit;
  const ShadowSettings& settings = scene.shadows;
  const Camera& camera = scene.camera;
  const uint32_t count = std::clamp<uint32_t>(settings.cascades, 1, abi::kMaxShadowCascades);
  const uint32_t atlas = settings.atlasSize;
  // The spot lights that cast take the cells after the cascades (spot_shadow.h).
  const auto views = uint32_t(count + shadowSpotLights(scene).size());
  const uint32_t size = shadowAtlasCell(atlas, views, 0)[2];

  const glm::dvec3 sunDirection = glm::normalize(scene.sun->direction);
  const glm::dmat3 toSun = sunFrame(sunDirection);
  const glm::dvec3 toTarget = camera.target - camera.position;
  const glm::dvec3 forward = glm::length(toTarget) > 0 ? glm::normalize(toTarget) : glm::dvec3(0, 0, -1);
  const double aspect = double(scene.width) / scene.height;
  const double tanHalfFov = std::tan(glm::radians(camera.fovYDegrees) / 2);
  const double cornerSlope = tanHalfFov * std::sqrt(1 + aspect * aspect);
  // Cascades cover the view from the near plane to the shadow distance, no further than the far
  // plane draws; a distance short of the near plane leaves slices of no depth at the near plane
  // (the fade below then lights every pixel).
  const double near = camera.nearPlane;
  const double far = std::max(near, std::min(settings.distance, camera.farPlane));

  for (uint32_t i = 0; i < count; ++i) {
    SunCascade c{};
    c.splitNear = practicalSplit(near, far, settings.splitLambda, i, count);
    c.splitFar = i + 1 == count ? far : practicalSplit(near, far, settings.splitLambda, i + 1, count);
    const SliceSphere sphere = sliceSphere(c.splitNear, c.splitFar, cornerSlope);
    c.center = camera.position + forward * sphere.depth;
    c.radius = sphere.radius;
    c.viewport = shadowAtlasCell(atlas, views, i);
    const double guard = shadowGuardTexels(settings.normalBias, size);
    c.texelSize = 2 * c.radius / (size - 2 * guard);
    const double halfWidth = 0.5 * size * c.texelSize;
    // Valient's snap: the square's centre at whole texels of the sun's frame.
    const glm::dvec3 sunCenter = toSun * c.center;
    const double x = std::round(sunCenter.x / c.texelSize) * c.texelSize;
    const double y = std::round(sunCenter.y / c.texelSize) * c.texelSize;
    // Depth: the sphere (and its guard) and, towards the sun, every caster that can shadow it.
    // Both ends at whole texels too, so that the depth a fixed point stores changes by whole
    // steps as the camera moves, as its texel does.
    double nearest = sunCenter.z - halfWidth;
    const double farthest = sunCenter.z + halfWidth;
    for (const CasterBounds& caster : casters)
      if (casterInCascade(c, caster, sunDirection))
        nearest = std::min(nearest, glm::dot(sunDirection, caster.center) - caster.radius);
    const double zNear = std::floor(nearest / c.texelSize) * c.texelSize;
    const double zFar = std::ceil(farthest / c.texelSize) * c.texelSize;
    c.depthRange = zFar - zNear;
    // The sun's frame → GL clip: x, y over the square, z from the nearest caster to the sphere's end.
    glm::dmat4 projection(1.0);
    projection[0][0] = 1 / halfWidth;
    projection[1][1] = 1 / halfWidth;
    projection[2][2] = 2 / c.depthRange;
    projection[3] = glm::dvec4(-x / halfWidth, -y / halfWidth, -2 * zNear / c.depthRange - 1, 1);
    c.viewProjection = projection * glm::dmat4(toSun);

    // The same map as the shaders read it, to atlas (u, v, depth): u = (vx + (X + 1)·w/2) / atlas
    // for clip X = (sx − x) / halfWidth, so scale w / (2·halfWidth·atlas) and the rest the offset.
    const double scale = size / (2 * halfWidth * atlas);
    const glm::dvec3 offset((c.viewport[0] + 0.5 * size) / atlas - x * scale,
                            (c.viewport[1] + 0.5 * size) / atlas - y * scale, -zNear / c.depthRange);
    store(fit.uniforms.cascadeScale[i], glm::dvec3(scale, scale, 1 / c.depthRange), settings.normalBias * c.texelSize);
    store(fit.uniforms.cascadeOffset[i], offset, 0);
    fit.uniforms.splits[i] = float(c.splitFar);
    fit.cascades.push_back(c);
  }
  // Entries past the last cascade repeat it (shader_abi.h): shadow_select's step() then picks it
  // for every depth past its split.
  for (uint32_t i = count; i < abi::kMaxShadowCascades; ++i) {
    std::copy_n(fit.uniforms.cascadeScale[count - 1], 4, fit.uniforms.cascadeScale[i]);
    std::copy_n(fit.uniforms.cascadeOffset[count - 1], 4, fit.uniforms.cascadeOffset[i]);
    fit.uniforms.splits[i] = fit.uniforms.splits[count - 1];
  }
  const glm::dmat4 lightView(toSun);
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) fit.uniforms.lightView[4 * column + row] = float(lightView[column][row]);
  store(fit.uniforms.cameraForward, forward, 0);
  // The fade: full shadow up to 90 % of the distance, none at the distance, linear between:
  // clamp(d·x + y, 0, 1) with x = 1 / (0.1·D), y = −0.9·D·x = −9.
  const double fadeScale = 1 / (0.1 * settings.distance);
  store(fit.uniforms.fadeAtlas, glm::dvec3(fadeScale, -9, atlas), 1.0 / atlas);
  return fit;
}

}  // namespace facet::runtime
