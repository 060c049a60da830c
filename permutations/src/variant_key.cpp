#include "facet/permutations/variant_key.h"

#include <algorithm>
#include <span>

namespace facet::permutations {

const char* toString(Tier t) {
  switch (t) {
    case Tier::Reference: return "reference";
    case Tier::High: return "high";
    case Tier::Mid: return "mid";
    case Tier::Low: return "low";
  }
  return "high";
}

std::optional<Tier> tierFromString(std::string_view s) {
  for (Tier t : {Tier::Reference, Tier::High, Tier::Mid, Tier::Low})
    if (s == toString(t)) return t;
  return std::nullopt;
}

std::optional<int> pointLightPermutation(int lights) {
  for (int count : kPointLightCounts)
    if (lights <= count) return count;
  return std::nullopt;
}

std::optional<int> shadowCascadePermutation(int cascades) {
  for (int count : kShadowCascadeCounts)
    if (cascades <= count) return count;
  return std::nullopt;
}

std::strong_ordering VariantKey::operator<=>(const VariantKey& o) const {
  if (auto c = tier <=> o.tier; c != 0) return c;
  if (auto c = depthOnly <=> o.depthOnly; c != 0) return c;
  if (auto c = vertexSlopeBias <=> o.vertexSlopeBias; c != 0) return c;
  if (auto c = directionalLight <=> o.directionalLight; c != 0) return c;
  if (auto c = pointLights <=> o.pointLights; c != 0) return c;
  if (auto c = shadowCascades <=> o.shadowCascades; c != 0) return c;
  return spotShadows <=> o.spotShadows;
}

std::string VariantKey::toString() const {
  if (depthOnly) return std::string(permutations::toString(tier)) + (vertexSlopeBias ? ".depth.slope" : ".depth");
  std::string s = std::string(permutations::toString(tier)) + (directionalLight ? ".dir1" : ".dir0");
  if (shadowCascades > 0) s += ".sh" + std::to_string(shadowCascades);
  if (pointLights > 0) s += ".pt" + std::to_string(pointLights);
  if (spotShadows > 0) s += ".sp" + std::to_string(spotShadows);
  return s;
}

std::optional<VariantKey> VariantKey::parse(std::string_view text) {
  std::vector<std::string_view> fields;
  for (size_t start = 0;;) {
    size_t dot = text.find('.', start);
    fields.push_back(text.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  if (fields.size() < 2 || fields.size() > 5) return std::nullopt;
  auto tier = tierFromString(fields[0]);
  if (tier && fields[1] == "depth") {
    if (fields.size() == 2) return depthKey(*tier);
    if (fields.size() == 3 && fields[2] == "slope") return depthKey(*tier, true);
    return std::nullopt;
  }
  if (!tier || (fields[1] != "dir0" && fields[1] != "dir1")) return std::nullopt;
  VariantKey key{*tier, fields[1] == "dir1", 0, 0};
  // The optional fields in their one order: "sh" (after dir1 only), then "pt", then "sp" (after
  // "pt" only).
  size_t next = 2;
  const auto field = [&](const char* prefix, std::span<const int> counts, int* value) {
    if (next >= fields.size()) return;
    for (int count : counts)
      if (count > 0 && fields[next] == prefix + std::to_string(count)) {
        *value = count;
        ++next;
        return;
      }
  };
  if (key.directionalLight) field("sh", kShadowCascadeCounts, &key.shadowCascades);
  field("pt", kPointLightCounts, &key.pointLights);
  static constexpr int kSpotShadowCounts[] = {0, kMaxSpotShadows};
  if (key.pointLights > 0) field("sp", kSpotShadowCounts, &key.spotShadows);
  if (next != fields.size()) return std::nullopt;
  return key;
}

const std::vector<Tier>& supportedTiers() {
  // Tiers whose shading maths this compiler version implements (see tiers.h for the presets).
  static const std::vector<Tier> tiers = {Tier::Reference, Tier::High, Tier::Mid, Tier::Low};
  return tiers;
}

bool blendingCastsShadows(std::string_view blending) { return blending == "opaque" || blending == "masked"; }

VariantKey depthKey(Tier tier, bool vertexSlopeBias) {
  VariantKey key{tier, false, 0, 0};
  key.depthOnly = true;
  key.vertexSlopeBias = vertexSlopeBias;
  return key;
}

VariantKey requestKey(const MaterialNeeds& material, Tier tier, bool directionalLight, int pointLights,
                      int shadowCascades, bool spotShadow) {
  const bool sun = material.lit && directionalLight;
  VariantKey key{tier, sun, material.lit ? pointLightPermutation(pointLights).value_or(0) : 0,
                 sun ? shadowCascadePermutation(shadowCascades).value_or(0) : 0};
  key.spotShadows = spotShadow && key.pointLights > 0 ? 1 : 0;
  return key;
}

std::vector<VariantKey> enumerate(const MaterialNeeds& material, const std::vector<Tier>& tiers,
                                  const SceneNeeds* scene, const std::vector<int>& pointLightCounts,
                                  const std::vector<int>& shadowCascadeCounts, bool spotShadows, bool vertexSlopeBias) {
  std::vector<VariantKey> keys;
  // A scene names its own counts; without one, the caller's lists apply.
  std::vector<int> counts =
      scene ? std::vector<int>(std::begin(kPointLightCounts), std::end(kPointLightCounts)) : pointLightCounts;
  std::vector<int> cascades =
      scene ? std::vector<int>(std::begin(kShadowCascadeCounts), std::end(kShadowCascadeCounts)) : shadowCascadeCounts;
  std::vector<bool> spots = scene || spotShadows ? std::vector<bool>{false, true} : std::vector<bool>{false};
  for (Tier t : tiers) {
    for (bool light : {false, true}) {
      for (int points : counts) {
        for (int shadow : cascades) {
          for (bool spot : spots) {
            VariantKey key = requestKey(material, t, light, points, shadow, spot);
            bool wanted = !scene || std::find(scene->keys.begin(), scene->keys.end(), key) != scene->keys.end();
            if (wanted) keys.push_back(key);
          }
        }
      }
    }
    // The shadow pass draws casters with it: built with the receivers, or when the scene asks.
    const bool shadows = spotShadows || std::any_of(cascades.begin(), cascades.end(), [](int c) { return c > 0; });
    for (bool slope : {false, true}) {
      const VariantKey depth = depthKey(t, slope);
      const bool asked = scene ? std::find(scene->keys.begin(), scene->keys.end(), depth) != scene->keys.end()
                               : shadows && (!slope || vertexSlopeBias);
      if (asked && material.castsShadows) keys.push_back(depth);
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace facet::permutations
