#include "facet/permutations/tiers.h"

namespace facet::permutations {

TierConfig preset(Tier tier) {
  switch (tier) {
    case Tier::Reference: return {SpecularModel::GgxSmith, DiffuseModel::Pixel, ColorSpace::Linear, PrecisionPolicy::Highp};
    case Tier::High: return {SpecularModel::GgxSmith, DiffuseModel::Pixel, ColorSpace::Linear, PrecisionPolicy::Mediump};
    case Tier::Mid: return {SpecularModel::Zioma, DiffuseModel::Vertex, ColorSpace::Linear, PrecisionPolicy::Mediump};
    case Tier::Low: return {SpecularModel::Lut, DiffuseModel::Vertex, ColorSpace::GammaHack, PrecisionPolicy::Mediump};
  }
  return {};
}

std::string describe(const TierConfig& c) {
  const char* specular[] = {"ggx_smith", "ggx_fastv", "zioma", "lut"};
  std::string s = specular[int(c.specular)];
  s += c.diffuse == DiffuseModel::Pixel ? ", pixel diffuse" : ", vertex diffuse";
  s += c.colorSpace == ColorSpace::Linear ? ", linear" : ", gamma_hack";
  s += c.precision == PrecisionPolicy::Highp ? ", highp" : ", mediump";
  return s;
}

}  // namespace facet::permutations
