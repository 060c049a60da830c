// A scene as the shadow reference reads it (facet/scene/scene.h reads and checks the shadow flags
// of the scene format, docs/shadows.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/scene/scene.h"

namespace facet::shadow_reference {

struct ShadowScene {
  runtime::Scene
      scene;  // the flags are the scene's own: sun->castShadows, each object's castShadows and receiveShadows
};

// Parses scene JSON with its shadow flags; errors are parseScene's.
std::optional<ShadowScene> parseShadowScene(const std::string& path, const std::string& text, std::string* error,
                                            const runtime::SceneReadOptions& options = {});
// Reads the file first, as loadScene (runtime::readSceneFile).
std::optional<ShadowScene> loadShadowScene(const std::string& path, std::string* error,
                                           const runtime::SceneReadOptions& options = {});

}  // namespace facet::shadow_reference
