// A scene as the shadow reference reads it: the scene itself (facet/scene/scene.h) and the
// shadow flags of the scene format (docs/shadows.md): the sun's `castShadows`, each object's
// `castShadows` and `receiveShadows` (default true), the `shadows` block. The flags are read
// here, from the file's JSON, and removed before the scene reader sees the rest, so that the
// reference reads the same flags whether or not the scene reader knows them.
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

// Parses scene JSON with its shadow flags. Errors as parseScene's: `<path>:<line>:<col>: error:
// ...` for the syntax, `<path>: error: <json pointer>: ...` for a wrong value (a flag that is not
// true or false, a `shadows` block that is not an object).
std::optional<ShadowScene> parseShadowScene(const std::string& path, const std::string& text, std::string* error,
                                            const runtime::SceneReadOptions& options = {});
// Reads the file first, as loadScene (runtime::readSceneFile).
std::optional<ShadowScene> loadShadowScene(const std::string& path, std::string* error,
                                           const runtime::SceneReadOptions& options = {});

}  // namespace facet::shadow_reference
