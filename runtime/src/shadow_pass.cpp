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

}  // namespace

ShadowPassDesc shadowPassDesc(const Scene& scene, const std::vector<CasterBounds>& bounds,
                              std::vector<DrawItem> casters) {
  ShadowPassDesc pass;
  pass.atlasSize = scene.shadows.atlasSize;
  if (scene.sun && scene.sun->castShadows) {
    const SunShadowFit fit = fitSunShadow(scene, bounds);
    pass.uniforms = fit.uniforms;
    for (const SunCascade& c : fit.cascades) {
      ShadowCascadeDesc d;
      store(d.viewProjection, c.viewProjection);
      std::copy(c.viewport.begin(), c.viewport.end(), d.viewport);
      // A texel's width along the rays, in window depth, is texelSize / depthRange.
      d.depthBias = float(scene.shadows.depthBias * c.texelSize / c.depthRange);
      d.slopeBias = float(scene.shadows.slopeBias);
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
    d.slopeBias = float(scene.shadows.slopeBias);
    for (size_t i = 0; i < bounds.size(); ++i)
      if (casterInSpotCone(spot, bounds[i])) d.casters.push_back(uint32_t(i));
    pass.cascades.push_back(std::move(d));
    ++pass.spotViews;
  }
  pass.casters = std::move(casters);
  return pass;
}

}  // namespace facet::runtime
