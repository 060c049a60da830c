#include "facet/shadow_reference/shadow_scene.h"

namespace facet::shadow_reference {

std::optional<ShadowScene> parseShadowScene(const std::string& path, const std::string& text, std::string* error,
                                            const runtime::SceneReadOptions& options) {
  std::optional<runtime::Scene> scene = runtime::parseScene(path, text, error, options);
  if (!scene) return std::nullopt;
  return ShadowScene{std::move(*scene)};
}

std::optional<ShadowScene> loadShadowScene(const std::string& path, std::string* error,
                                           const runtime::SceneReadOptions& options) {
  std::optional<std::string> text = runtime::readSceneFile(path, error);
  if (!text) return std::nullopt;
  return parseShadowScene(path, *text, error, options);
}

}  // namespace facet::shadow_reference
