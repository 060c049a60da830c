// A variant key names one permutation of a material: one value per axis. Its string form is
// stable across compiler versions (apps store it), e.g. "high.dir1", "mid.dir0.pt2" or
// "low.dir1.sh4.pt1":
//   <tier> "." "dir" <0|1> [ "." "sh" <1|2|4> ] [ "." "pt" <1|2|4> [ "." "sp1" ] ]
// or, for the shadow pass's depth-only program of a tier, <tier> "." "depth" [ "." "slope" ] (e.g.
// "mid.depth"; "mid.depth.slope" adds the slope bias in its vertex stage, docs/shadows.md "Bias").
// The shadow field follows dir1 only (the sun is what casts); the spot-shadow field follows a
// point-light field only (light slot 0 is the casting spot). The shadow and point-light fields
// are absent when their count is 0, so keys written before an axis existed still name the same
// variants. A reader that meets a field it does not know rejects the key
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

// Sun shadows likewise: a receiver variant reads cascades 0..N-1 of the shadow block; a scene
// with 3 cascades uses the 4-cascade variant (the 4th never selected: its split is the fade's end).
inline constexpr int kShadowCascadeCounts[] = {0, 1, 2, 4};
inline constexpr int kMaxShadowCascades = 4;
// The receiver permutation for `cascades` sun cascades (0: no shadow), or nullopt beyond
// kMaxShadowCascades.
std::optional<int> shadowCascadePermutation(int cascades);

// A casting spot light's shadow (docs/shadows.md, "Spot shadows"): a receiver reads it for light
// slot 0, where the runtime puts the scene's one casting spot; 0 or 1.
inline constexpr int kMaxSpotShadows = 1;

struct VariantKey {
  Tier tier = Tier::High;
  bool directionalLight = true;
  int pointLights = 0;     // one of kPointLightCounts
  int shadowCascades = 0;  // one of kShadowCascadeCounts; non-zero only with directionalLight
  // The shadow pass's depth-only program (position only; a masked material's alpha test): no
  // lights, no shadow, no point lights. Its tier picks the alpha test's precision.
  bool depthOnly = false;
  // With depthOnly: the vertex stage reads the normal and adds the slope bias to the clip depth
  // itself (Guo and Li's vertex-stage slope bias; the scene's shadows.slopeStage "vertex").
  bool vertexSlopeBias = false;
  int spotShadows = 0;  // 0 or 1: light slot 0's shadow is received; non-zero only with pointLights

  // Whether the variant samples the shadow atlas (a sun or a spot shadow receiver).
  bool receivesShadow() const { return shadowCascades > 0 || spotShadows > 0; }
  std::string toString() const;
  static std::optional<VariantKey> parse(std::string_view text);
  // A tier's forward variants, then its depth-only program.
  std::strong_ordering operator<=>(const VariantKey& other) const;
  bool operator==(const VariantKey&) const = default;
};

// What a material needs from the permutation space (filled from the IR by the compiler, or
// from a package's metadata by the runtime).
struct MaterialNeeds {
  bool lit = true;
  // Whether its objects can cast the sun's shadow: opaque and masked materials; transparent and
  // additive ones do not cast (a shadow map stores one depth, not a coverage).
  bool castsShadows = true;
};

// Whether a material of this blending mode casts shadows (MaterialNeeds::castsShadows).
bool blendingCastsShadows(std::string_view blending);

// The key of a tier's depth-only program (VariantKey::depthOnly), with the vertex-stage slope bias
// or without.
VariantKey depthKey(Tier tier, bool vertexSlopeBias = false);

// The variants a scene asks a material for (filled by matc from a scene manifest).
struct SceneNeeds {
  std::vector<VariantKey> keys;
};

// The key a renderer asks for: the scene's tier, whether a directional light is present, the
// point-light permutation (pointLightPermutation of the frame's count), the sun's shadow
// cascades as the object receives them (shadowCascadePermutation; 0 for an object that does not
// receive, or when nothing casts) and whether it receives a casting spot's shadow (light slot 0). Axes the material
// ignores are normalised (an unlit material has only dir0, no point lights and no shadows; no sun, no shadow), so
// compiler and runtime agree on the key without either knowing the other.
VariantKey requestKey(const MaterialNeeds& material, Tier tier, bool directionalLight, int pointLights = 0,
                      int shadowCascades = 0, bool spotShadow = false);

// Every variant the given tiers, point-light counts and shadow-cascade counts allow for the
// material, in a stable (sorted) order; with a scene, exactly those of the scene's keys the tiers
// allow (the scene's own counts, whatever the lists say). A non-zero shadow count, or spot
// shadows, adds each tier's depth-only program for a material that casts. With spotShadows, every
// variant with point lights comes with and without `.sp1`. With vertexSlopeBias, the depth-only
// programs come with and without the vertex-stage slope bias (`.depth.slope`).
std::vector<VariantKey> enumerate(const MaterialNeeds& material, const std::vector<Tier>& tiers,
                                  const SceneNeeds* scene = nullptr, const std::vector<int>& pointLightCounts = {0},
                                  const std::vector<int>& shadowCascadeCounts = {0}, bool spotShadows = false,
                                  bool vertexSlopeBias = false);

// Tiers this compiler version builds shaders for.
const std::vector<Tier>& supportedTiers();

}  // namespace facet::permutations
