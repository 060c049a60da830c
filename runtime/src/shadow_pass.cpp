#include "facet/runtime/shadow_pass.h"

#include <algorithm>
#include <cstring>

#include <glm/gtc/type_ptr.hpp>

#include "facet/runtime/spot_shadow.h"

namespace facet::runtime {

namespace {

void store(float* dst, const glm::dmat4& m) {
  const glm::mat4 f(m);
  std::memcpy(dst, glm::value_ptr(f), sizeof(float) * 16);
}

// The slope bias where the scene puts it: the rasteriser's factor, or the vertex stage's constant,
// axis and light (ShadowCascadeDesc::vertexSlopeBias) with the rasteriser's factor 0.
void setSlopeBias(const ShadowSettings& settings, double vertexConstant, const glm::dvec3& axis,
                  const glm::dvec4& light, ShadowCascadeDesc* d) {
  if (settings.slopeStage == SlopeBiasStage::Raster) {
    d->slopeBias = float(settings.slopeBias);
    return;
  }
  d->vertexSlopeBias = float(vertexConstant);
  for (int i = 0; i < 3; ++i) d->lightAxis[i] = float(axis[i]);
  for (int i = 0; i < 4; ++i) d->lightPosition[i] = float(light[i]);
}

}  // namespace

ShadowPassDesc shadowPassDesc(const Scene& scene, const std::vector<CasterBounds>& bounds,
                              std::vector<DrawItem> casters) {
  ShadowPassDesc pass;
  pass.atlasSize = scene.shadows.atlasSize;
  // The filters' atlas size (chunks/shadow_filter.glsl), whichever light casts.
  pass.uniforms.fadeAtlas[2] = float(pass.atlasSize);
  pass.uniforms.fadeAtlas[3] = float(1.0 / pass.atlasSize);
  if (scene.sun && scene.sun->castShadows) {
    const SunShadowFit fit = fitSunShadow(scene, bounds);
    pass.uniforms = fit.uniforms;
    for (const SunCascade& c : fit.cascades) {
      ShadowCascadeDesc d;
      store(d.viewProjection, c.viewProjection);
      std::copy(c.viewport.begin(), c.viewport.end(), d.viewport);
      // A texel's width along the rays, in window depth, is texelSize / depthRange.
      d.depthBias = float(scene.shadows.depthBias * c.texelSize / c.depthRange);
      // A surface at angle θ to the rays changes window depth by tan θ × texelSize / depthRange per
      // texel: what the rasteriser's slope factor multiplies, and the vertex stage's constant (w 1).
      setSlopeBias(scene.shadows, scene.shadows.slopeBias * c.texelSize / c.depthRange,
                   -glm::normalize(scene.sun->direction), glm::dvec4(0.0), &d);
      for (size_t i = 0; i < bounds.size(); ++i)
        if (casterInCascade(c, bounds[i], scene.sun->direction)) d.casters.push_back(uint32_t(i));
      pass.cascades.push_back(std::move(d));
    }
  }
  const std::vector<size_t> spots = shadowSpotLights(scene);
  const auto views = uint32_t(pass.cascades.size() + spots.size());
  for (size_t light : spots) {
    const auto cell = shadowAtlasCell(pass.atlasSize, views, uint32_t(pass.cascades.size()));
    const SpotShadow spot = fitSpotShadow(scene, light, cell);
    ShadowCascadeDesc d;
    store(d.viewProjection, spot.viewProjection);
    std::copy(spot.viewport.begin(), spot.viewport.end(), d.viewport);
    d.depthBias = float(spotDepthBias(spot, scene.shadows.depthBias));
    setSlopeBias(scene.shadows, spotVertexSlopeBias(spot, scene.shadows.slopeBias), -spot.axis,
                 glm::dvec4(spot.position, 1.0), &d);
    for (size_t i = 0; i < bounds.size(); ++i)
      if (casterInSpotCone(spot, bounds[i])) d.casters.push_back(uint32_t(i));
    pass.cascades.push_back(std::move(d));
    ++pass.spotViews;
    // What `.sp1` receivers read for light slot 0 (SceneFrame puts the casting spot there;
    // templates/forward.vert.glsl): the view and the normal offset per metre of distance along
    // its axis, normalBias texels of the view at that distance.
    store(pass.uniforms.spotAtlasFromWorld, spot.atlasFromWorld);
    pass.uniforms.spotNormalOffset[0] = float(scene.shadows.normalBias * spot.texelPerMetre);
  }
  pass.casters = std::move(casters);
  return pass;
}

}  // namespace facet::runtime
