#include "scene_keys.h"

#include <algorithm>

namespace facet::matc {

std::optional<runtime::Scene> loadSceneManifest(const std::string& path, std::string* error) {
  return runtime::loadScene(path, error, runtime::SceneReadOptions{.assetRoot = "/"});
}

std::optional<std::vector<permutations::VariantKey>> sceneKeysFor(const runtime::Scene& scene,
                                                                  const std::string& scenePath,
                                                                  const std::string& material,
                                                                  const permutations::MaterialNeeds& needs,
                                                                  std::string* error) {
  auto tier = permutations::tierFromString(scene.tier);
  if (!tier) {
    *error = scenePath + ": unknown tier '" + scene.tier + "'";
    return std::nullopt;
  }
  bool used = std::any_of(scene.objects.begin(), scene.objects.end(),
                          [&](const runtime::SceneObject& o) { return o.material == material; });
  if (!used) {
    *error = scenePath + ": no object of the scene uses material '" + material + "'";
    return std::nullopt;
  }
  // Every object of a material shares the scene's lights; only receiving the shadows differs.
  std::vector<permutations::VariantKey> keys;
  const bool spotCasts = !runtime::shadowSpotLights(scene).empty();
  const bool anythingCasts = runtime::sunShadowCascades(scene) > 0 || spotCasts;
  for (const runtime::SceneObject& o : scene.objects) {
    if (o.material != material) continue;
    const int cascades = o.receiveShadows ? int(runtime::sunShadowCascades(scene)) : 0;
    keys.push_back(permutations::requestKey(needs, *tier, scene.sun.has_value(), int(scene.lights.size()), cascades,
                                            o.receiveShadows && spotCasts));
    if (o.castShadows && needs.castsShadows && anythingCasts)
      keys.push_back(permutations::depthKey(*tier, scene.shadows.slopeStage == runtime::SlopeBiasStage::Vertex));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace facet::matc
