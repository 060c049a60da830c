#include "facet/permutations/variant_key.h"

#include <algorithm>

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

std::string VariantKey::toString() const {
  return std::string(permutations::toString(tier)) + (directionalLight ? ".dir1" : ".dir0");
}

std::optional<VariantKey> VariantKey::parse(std::string_view text) {
  size_t dot = text.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  auto tier = tierFromString(text.substr(0, dot));
  std::string_view light = text.substr(dot + 1);
  if (!tier || (light != "dir0" && light != "dir1")) return std::nullopt;
  return VariantKey{*tier, light == "dir1"};
}

const std::vector<Tier>& supportedTiers() {
  // Tiers whose shading maths this compiler version implements (see tiers.h for the presets).
  static const std::vector<Tier> tiers = {Tier::Reference, Tier::High, Tier::Mid, Tier::Low};
  return tiers;
}

VariantKey requestKey(const MaterialNeeds& material, Tier tier, bool directionalLight) {
  return {tier, material.lit && directionalLight};
}

std::vector<VariantKey> enumerate(const MaterialNeeds& material, const std::vector<Tier>& tiers, const SceneNeeds* scene) {
  std::vector<VariantKey> keys;
  for (Tier t : tiers) {
    for (bool light : {false, true}) {
      VariantKey key = requestKey(material, t, light);
      bool wanted = !scene || std::find(scene->keys.begin(), scene->keys.end(), key) != scene->keys.end();
      if (wanted) keys.push_back(key);
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace facet::permutations
