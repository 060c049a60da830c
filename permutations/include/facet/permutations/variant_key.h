// A variant key names one permutation of a material: one value per axis. Its string form is
// stable across compiler versions (apps store it), e.g. "high.dir1":
//   <tier> "." "dir" <0|1>
// More axes append more dot-separated fields; a reader that meets a field it does not know
// rejects the key rather than guessing.
#pragma once

#include <compare>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::permutations {

// GPU tiers (DESIGN.md, "Tiers"). Each picks its own shading maths.
enum class Tier { Reference, High, Mid, Low };
const char* toString(Tier);
std::optional<Tier> tierFromString(std::string_view);

struct VariantKey {
  Tier tier = Tier::High;
  bool directionalLight = true;

  std::string toString() const;
  static std::optional<VariantKey> parse(std::string_view text);
  auto operator<=>(const VariantKey&) const = default;
};

// What a material needs from the permutation space (filled from the IR by the compiler, or
// from a package's metadata by the runtime).
struct MaterialNeeds {
  bool lit = true;
};

// The variants a scene asks a material for (filled by matc from a scene manifest).
struct SceneNeeds {
  std::vector<VariantKey> keys;
};

// The key a renderer asks for: the scene's tier, and whether a directional light is present.
// Axes the material ignores are normalised (an unlit material has only dir0), so compiler and
// runtime agree on the key without either knowing the other.
VariantKey requestKey(const MaterialNeeds& material, Tier tier, bool directionalLight);

// Every variant the given tiers allow for the material, in a stable (sorted) order; with a
// scene, only those the scene asks for.
std::vector<VariantKey> enumerate(const MaterialNeeds& material, const std::vector<Tier>& tiers,
                                  const SceneNeeds* scene = nullptr);

// Tiers this compiler version builds shaders for.
const std::vector<Tier>& supportedTiers();

}  // namespace facet::permutations
