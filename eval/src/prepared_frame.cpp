#include "facet/eval/prepared_frame.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "facet/runtime/material.h"

namespace facet::eval {
namespace {

using permutations::TierConfig;

runtime::ColorEncoding encoding(const TierConfig& c) {
  return c.colorSpace == permutations::ColorSpace::GammaHack ? runtime::ColorEncoding::Srgb
                                                             : runtime::ColorEncoding::Linear;
}

// Same position, rotation and scale: the draw's first instance is the object's transform, rounded
// to float (the draws of one instanced group share their parameters and textures, so the first
// object stands for them all).
bool samePlace(const runtime::DrawItem& draw, const runtime::SceneObject& o) {
  const glm::dmat4 model = runtime::modelMatrix(o);
  const abi::InstanceTransform& t = draw.instances.front();
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) {
      const double want = model[column][row];
      if (std::abs(t.rows[row][column] - want) > 1e-5 * std::max(1.0, std::abs(want))) return false;
    }
  return true;
}

}  // namespace

std::unique_ptr<PreparedFrame> PreparedFrame::prepare(const runtime::Scene& scene, const std::string& packageDir,
                                                      const TierConfig& config, std::string* error) {
  auto tier = permutations::tierFromString(scene.tier);
  if (!tier) {
    *error = "unknown tier '" + scene.tier + "'";
    return nullptr;
  }
  std::unique_ptr<PreparedFrame> out(new PreparedFrame());
  out->scene_ = runtime::SceneFrame::prepare(scene, packageDir, error);
  if (!out->scene_) return nullptr;
  out->frame_ = out->scene_->frame();
  if (!out->adapt(scene, packageDir, permutations::preset(*tier), config, error)) return nullptr;
  return out;
}

bool PreparedFrame::adapt(const runtime::Scene& scene, const std::string& packageDir, const TierConfig& preset,
                          const TierConfig& config, std::string* error) {
  if (encoding(config) == encoding(preset)) return true;
  const bool wantSrgb = encoding(config) == runtime::ColorEncoding::Srgb;
  std::map<std::string, std::unique_ptr<runtime::LoadedMaterial>> materials;
  for (runtime::DrawItem& draw : frame_.draws) {
    // The environment drawn as the background (runtime/background.h) is no object of the scene:
    // its block is the background's own and its program no material's, the same in every
    // encoding (a scene with an environment shows it unless it says "show": "flat").
    if (draw.atFarPlane) continue;
    // The object this draw came from: same place and size, and the parameter block SceneFrame made
    // from its values; its block is made again in the configuration's encoding.
    bool matched = false;
    for (const runtime::SceneObject& o : scene.objects) {
      if (!samePlace(draw, o)) continue;
      auto& material = materials[o.material];
      if (!material) {
        auto loaded = runtime::LoadedMaterial::load(
            (std::filesystem::path(packageDir) / (o.material + ".matpkg")).string(), error);
        if (!loaded) return false;
        material = std::make_unique<runtime::LoadedMaterial>(std::move(*loaded));
      }
      // Both blocks completed by the variant's preshader, as SceneFrame completes its own.
      const std::string& key = scene_->variantKey();
      auto prepared = material->paramBlock(o.params, error, encoding(preset));
      if (!prepared || !material->preshade(key, &*prepared, error)) return false;
      if (*prepared != draw.materialParams) continue;
      auto wanted = material->paramBlock(o.params, error, encoding(config));
      auto sampled = material->sampledTextures(o.textures, error);
      if (!wanted || !sampled || !material->preshade(key, &*wanted, error)) return false;
      draw.materialParams = std::move(*wanted);
      for (const auto& t : *sampled) {
        if (!t.srgb) continue;
        for (runtime::TextureBinding& b : draw.textures)
          if (b.binding == abi::kMaterialTextureBase + t.slot) b.texture = recoded(b.texture, wantSrgb);
      }
      matched = true;
      break;
    }
    if (!matched) {
      *error = "internal error: a draw of the prepared frame matches no object of the scene";
      return false;
    }
  }
  return true;
}

// The texture with the sampler's sRGB decoding on (linear lighting) or off (the gamma hack).
const runtime::Texture* PreparedFrame::recoded(const runtime::Texture* t, bool srgbEncodedInShader) {
  const runtime::TextureFormat want =
      srgbEncodedInShader ? runtime::TextureFormat::Rgba8Unorm : runtime::TextureFormat::Rgba8Srgb;
  if (t->format == want ||
      (t->format != runtime::TextureFormat::Rgba8Unorm && t->format != runtime::TextureFormat::Rgba8Srgb))
    return t;
  auto key = std::make_pair(t, want);
  if (auto it = copies_.find(key); it != copies_.end()) return it->second;
  textures_.push_back(*t);
  textures_.back().format = want;
  return copies_[key] = &textures_.back();
}

}  // namespace facet::eval
