// The variant a scene manifest asks a material for: the one place matc turns a scene into a
// VariantKey (compile --scene builds it, info --scene checks the package has it), with the same
// requestKey the runtime uses when it renders that scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/permutations/variant_key.h"
#include "facet/scene/scene.h"

namespace facet::matc {

// Reads a scene as a manifest: which materials, tier and lights it uses. matc never opens the
// images a scene names, so it does not confine them to the scene's folder as a renderer must.
std::optional<runtime::Scene> loadSceneManifest(const std::string& path, std::string* error);

// The keys the scene's objects of this material ask for, sorted: one, or two when the sun or a
// spot light casts and some of them receive its shadow while others do not (`receiveShadows`);
// and the tier's depth-only program when the sun or a spot casts and one of them casts (`castShadows`, a material that
// casts: MaterialNeeds::castsShadows). Nullopt, with *error set, when the scene's tier is unknown
// or no object of the scene uses the material.
std::optional<std::vector<permutations::VariantKey>> sceneKeysFor(const runtime::Scene& scene,
                                                                  const std::string& scenePath,
                                                                  const std::string& material,
                                                                  const permutations::MaterialNeeds& needs,
                                                                  std::string* error);

}  // namespace facet::matc
