#include "facet/shadow_reference/shadow_scene.h"

namespace facet::shadow_reference {

std::optional<ShadowScene> parseShadowScene(const std::string& path, const std::string& text, std::string* error,
                                            const runtime::SceneReadOptions& options) {
  std::optional<runtime::Scene> scene = runtime::parseScene(path, text, error, options);
  if (!scene) return std::nullopt;
  ShadowScene out;
  out.sunCastsShadows = scene->sun && scene->sun->castShadows;
  for (const runtime::SceneObject& o : scene->objects) {
    out.casts.push_back(o.castShadows);
    out.receives.push_back(o.receiveShadows);
  }
  out.scene = std::move(*scene);
  return out;
}

std::optional<ShadowScene> loadShadowScene(const std::string& path, std::string* error,
                                           const runtime::SceneReadOptions& options) {
  std::optional<std::string> text = runtime::readSceneFile(path, error);
  if (!text) return std::nullopt;
  return parseShadowScene(path, *text, error, options);
}

}  // namespace facet::shadow_reference
