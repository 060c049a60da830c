// A scene as the shadow reference reads it: the scene itself (facet/scene/scene.h, which reads
// and checks the shadow flags of the scene format, docs/shadows.md) and those flags gathered in
// scene order: the sun's `castShadows`, each object's `castShadows` and `receiveShadows`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/scene/scene.h"

namespace facet::shadow_reference {

struct ShadowScene {
  runtime::Scene scene;
  bool sunCastsShadows = false;  // the sun's `castShadows`: whether the renderer draws its shadow
  // Per object, in scene order: drawn into the shadow map (castShadows), darkened by it
  // (receiveShadows).
  std::vector<bool> casts;
  std::vector<bool> receives;
};

// Parses scene JSON with its shadow flags; errors are parseScene's.
std::optional<ShadowScene> parseShadowScene(const std::string& path, const std::string& text, std::string* error,
                                            const runtime::SceneReadOptions& options = {});
// Reads the file first, as loadScene (runtime::readSceneFile).
std::optional<ShadowScene> loadShadowScene(const std::string& path, std::string* error,
                                           const runtime::SceneReadOptions& options = {});

}  // namespace facet::shadow_reference
