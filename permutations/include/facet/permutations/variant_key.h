// A variant key names one permutation of a material: one value per axis. Its string form is
// stable across compiler versions (apps store it), e.g. "high.dir1" or "mid.dir0.pt2":
//   <tier> "." "dir" <0|1> [ "." "pt" <1|2|4> ]
// The point-light field is absent when the count is 0, so keys written before the axis existed
// still name the same variants. A reader that meets a field it does not know rejects the key
// rather than guessing.
#pragma once

#include <compare>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::permutations {

// GPU tiers (docs/architecture.md, "Tiers"). Each picks its own shading maths.
enum class Tier { Reference, High, Mid, Low };
const char* toString(Tier);
std::optional<Tier> tierFromString(std::string_view);

// Punctual (point and spot) lights come in fixed-count permutations: the shader reads lights
// 0..N-1 from fixed uniform addresses, unrolled, with no dynamic indexing. A frame with a count
// between two permutations uses the next larger one, padded with lights of zero intensity.
inline constexpr int kPointLightCounts[] = {0, 1, 2, 4};
inline constexpr int kMaxPointLights = 4;
// The permutation a frame with `lights` punctual lights uses, or nullopt if there are more than
// kMaxPointLights.
std::optional<int> pointLightPermutation(int lights);

struct VariantKey {
  Tier tier = Tier::High;
  bool directionalLight = true;
  int pointLights = 0;  // one of kPointLightCounts

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

// The key a renderer asks for: the scene's tier, whether a directional light is present, and the
// point-light permutation (pointLightPermutation of the frame's count). Axes the material
// ignores are normalised (an unlit material has only dir0 and no point lights), so compiler and
// runtime agree on the key without either knowing the other.
VariantKey requestKey(const MaterialNeeds& material, Tier tier, bool directionalLight, int pointLights = 0);

// Every variant the given tiers and point-light counts allow for the material, in a stable
// (sorted) order; with a scene, exactly those of the scene's keys the tiers allow (the scene's
// own point-light counts, whatever pointLightCounts says).
std::vector<VariantKey> enumerate(const MaterialNeeds& material, const std::vector<Tier>& tiers,
                                  const SceneNeeds* scene = nullptr, const std::vector<int>& pointLightCounts = {0});

// Tiers this compiler version builds shaders for.
const std::vector<Tier>& supportedTiers();

}  // namespace facet::permutations
