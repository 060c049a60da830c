#include "scene_keys.h"

#include <algorithm>

namespace facet::matc {

std::optional<runtime::Scene> loadSceneManifest(const std::string& path, std::string* error) {
  return runtime::loadScene(path, error, runtime::SceneReadOptions{.assetRoot = "/"});
}

std::optional<permutations::VariantKey> sceneKeyFor(const runtime::Scene& scene, const std::string& scenePath,
                                                    const std::string& material, bool lit, std::string* error) {
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
  // Every object of a material shares the scene's lights, so they all ask for one key.
  return permutations::requestKey({lit}, *tier, scene.sun.has_value(), int(scene.lights.size()));
}

}  // namespace facet::matc
