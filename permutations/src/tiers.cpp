#include "facet/permutations/tiers.h"

#include <iterator>

namespace facet::permutations {
namespace {

// Each tier's choices but the ambient occlusion's (preset sets those).
TierConfig shadingPreset(Tier tier) {
  switch (tier) {
    case Tier::Reference:
      return {SpecularModel::GgxSmith,
              DiffuseModel::Pixel,
              ColorSpace::Linear,
              PrecisionPolicy::Highp,
              AmbientModel::SplitSum,
              3,
              true,
              ClearCoatModel::GgxKelemen,
              AnisotropyModel::GgxSmith};
    case Tier::High:
      return {SpecularModel::GgxSmith,
              DiffuseModel::Pixel,
              ColorSpace::Linear,
              PrecisionPolicy::Mediump,
              AmbientModel::SplitSum,
              3,
              true,
              ClearCoatModel::GgxKelemen,
              AnisotropyModel::GgxSmith};
    case Tier::Mid:
      return {SpecularModel::FusedHammon,
              DiffuseModel::Vertex,
              ColorSpace::Linear,
              PrecisionPolicy::Mediump,
              AmbientModel::SplitSum,
              3,
              true,
              ClearCoatModel::Ambient,
              AnisotropyModel::None,
              ShadowFilter::OneTap};
    case Tier::Low:
      return {SpecularModel::Lut,
              DiffuseModel::Vertex,
              ColorSpace::Linear,
              PrecisionPolicy::Mediump,
              AmbientModel::SplitSum,
              2,
              true,
              ClearCoatModel::Ambient,
              AnisotropyModel::None,
              ShadowFilter::OneTap};
  }
  return {};
}

}  // namespace

TierConfig preset(Tier tier) {
  TierConfig config = shadingPreset(tier);
  // mid and low: specular occlusion costs them what it costs high (Mesa's Mali-G57), beyond half of
  // it, for 1.1 and 0.5 dB on painted_tiles: dropped. Multi-bounce AO is kept at its full cost:
  // without it they lose 14.3 and 10.2 dB there (docs/material-models.md).
  if (tier == Tier::Mid || tier == Tier::Low) config.specularOcclusion = SpecularOcclusionModel::Ao;
  // mid and low: specular anti-aliasing costs them its derivatives (+0.3 Mali-G57 cycles). Against
  // 16 samples per pixel (docs/material-models.md) mid gains on the outdoor hammered floor (+2 dB
  // at variance 0.02) and loses on the glint floor (a delta light's sub-pixel glints, -4.5 dB);
  // low loses on both (its table's ceiling): dropped, mid for its cost.
  if (tier == Tier::Mid || tier == Tier::Low) config.specularAntiAliasing = SpecularAntiAliasingModel::None;
  return config;
}

bool applyOverride(TierConfig* config, const std::string& axis, const std::string& option) {
  if (axis == "specular") {
    for (size_t i = 0; i < std::size(kSpecularModelNames); ++i) {
      if (option == kSpecularModelNames[i]) {
        config->specular = SpecularModel(i);
        return true;
      }
    }
  }
  if (axis == "diffuse") {
    for (size_t i = 0; i < std::size(kDiffuseModelNames); ++i) {
      if (option == kDiffuseModelNames[i]) {
        config->diffuse = DiffuseModel(i);
        return true;
      }
    }
  }
  if (axis == "clear_coat") {
    for (size_t i = 0; i < std::size(kClearCoatModelNames); ++i) {
      if (option == kClearCoatModelNames[i]) {
        config->clearCoat = ClearCoatModel(i);
        return true;
      }
    }
  }
  if (axis == "anisotropy") {
    for (size_t i = 0; i < std::size(kAnisotropyModelNames); ++i) {
      if (option == kAnisotropyModelNames[i]) {
        config->anisotropy = AnisotropyModel(i);
        return true;
      }
    }
  }
  if (axis == "ao") {
    for (size_t i = 0; i < std::size(kAmbientOcclusionModelNames); ++i) {
      if (option == kAmbientOcclusionModelNames[i]) {
        config->ambientOcclusion = AmbientOcclusionModel(i);
        return true;
      }
    }
  }
  if (axis == "specular_occlusion") {
    for (size_t i = 0; i < std::size(kSpecularOcclusionModelNames); ++i) {
      if (option == kSpecularOcclusionModelNames[i]) {
        config->specularOcclusion = SpecularOcclusionModel(i);
        return true;
      }
    }
  }
  if (axis == "specular_aa") {
    for (size_t i = 0; i < std::size(kSpecularAntiAliasingModelNames); ++i) {
      if (option == kSpecularAntiAliasingModelNames[i]) {
        config->specularAntiAliasing = SpecularAntiAliasingModel(i);
        return true;
      }
    }
  }
  if (axis == "sheen") {
    for (size_t i = 0; i < std::size(kSheenModelNames); ++i) {
      if (option == kSheenModelNames[i]) {
        config->sheen = SheenModel(i);
        return true;
      }
    }
  }
  return false;
}

std::string describe(const TierConfig& c) {
  std::string s = kSpecularModelNames[int(c.specular)];
  s += std::string(", ") + kDiffuseModelNames[int(c.diffuse)] + " diffuse";
  s += c.colorSpace == ColorSpace::Linear ? ", linear" : ", gamma_hack";
  s += c.precision == PrecisionPolicy::Highp ? ", highp" : ", mediump";
  const char* ambient[] = {"split_sum", "analytic_env_brdf", "two_mip", "sampled"};
  s += std::string(", ") + ambient[int(c.ambient)];
  if (c.ambient == AmbientModel::Sampled)
    s += " (" + std::to_string(c.ambientSamples) + " samples)";
  else if (c.diffuse == DiffuseModel::Cube)
    s += " + irradiance cube";
  else
    s += " + sh" + std::to_string(c.shBands);
  if (c.energyCompensation) s += ", energy compensation";
  if (c.dominantDirection) s += ", dominant direction";
  return s;
}

}  // namespace facet::permutations
