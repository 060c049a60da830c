#include "facet/eval/configurations.h"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "facet/compiler/build.h"

namespace facet::eval {
namespace {

using permutations::AmbientModel;
using permutations::ColorSpace;
using permutations::DiffuseModel;
using permutations::PrecisionPolicy;
using permutations::SpecularModel;
using permutations::TierConfig;

const char* const kAmbient[] = {"split_sum", "analytic", "two_mip", "sampled"};

}  // namespace

const std::vector<Axis>& axes() {
  static const std::vector<Axis> list = {
      {"specular",
       {std::begin(permutations::kSpecularModelNames), std::end(permutations::kSpecularModelNames)},
       [](const TierConfig& c) { return std::string(permutations::kSpecularModelNames[int(c.specular)]); },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "specular", o); },
       nullptr,
       [](const ir::Material& m) { return !m.cloth; }},  // the cloth model has no specular lobe
      {"diffuse",
       {std::begin(permutations::kDiffuseModelNames), std::end(permutations::kDiffuseModelNames)},
       [](const TierConfig& c) { return std::string(permutations::kDiffuseModelNames[int(c.diffuse)]); },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "diffuse", o); }},
      {"ambient",
       {"split_sum", "analytic", "two_mip"},
       [](const TierConfig& c) { return std::string(kAmbient[int(c.ambient)]); },
       [](TierConfig* c, const std::string& o) {
         c->ambient = o == "split_sum"  ? AmbientModel::SplitSum
                      : o == "analytic" ? AmbientModel::Analytic
                                        : AmbientModel::TwoMip;
       }},
      // 5: bands l = 0..4, SH3 and band 4 (docs/ibl.md; band 3 vanishes under the clamped cosine)
      {"sh_bands",
       {"2", "3", "5"},
       [](const TierConfig& c) { return std::to_string(c.shBands); },
       [](TierConfig* c, const std::string& o) { c->shBands = o == "2"   ? 2
                                                              : o == "5" ? 5
                                                                         : 3; },
       // the irradiance cube tabulates SH3 whatever the tier's bands
       [](const TierConfig& c) { return c.diffuse != DiffuseModel::Cube; }},
      {"color_space",
       {"linear", "gamma_hack"},
       [](const TierConfig& c) { return std::string(c.colorSpace == ColorSpace::Linear ? "linear" : "gamma_hack"); },
       [](TierConfig* c, const std::string& o) {
         c->colorSpace = o == "linear" ? ColorSpace::Linear : ColorSpace::GammaHack;
       }},
      {"precision",
       {"highp", "mediump"},
       [](const TierConfig& c) { return std::string(c.precision == PrecisionPolicy::Highp ? "highp" : "mediump"); },
       [](TierConfig* c, const std::string& o) {
         c->precision = o == "highp" ? PrecisionPolicy::Highp : PrecisionPolicy::Mediump;
       }},
      {"energy_compensation",
       {"off", "on"},
       [](const TierConfig& c) { return std::string(c.energyCompensation ? "on" : "off"); },
       [](TierConfig* c, const std::string& o) { c->energyCompensation = o == "on"; },
       [](const TierConfig& c) { return c.ambient == AmbientModel::SplitSum; },
       [](const ir::Material& m) { return !m.cloth; }},
      {"dominant_direction",
       {"off", "on"},
       [](const TierConfig& c) { return std::string(c.dominantDirection ? "on" : "off"); },
       [](TierConfig* c, const std::string& o) { c->dominantDirection = o == "on"; },
       nullptr,
       [](const ir::Material& m) { return !m.cloth; }},
      {"clear_coat",
       {std::begin(permutations::kClearCoatModelNames), std::end(permutations::kClearCoatModelNames)},
       [](const TierConfig& c) { return std::string(permutations::kClearCoatModelNames[int(c.clearCoat)]); },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "clear_coat", o); },
       nullptr,
       [](const ir::Material& m) { return m.shading == "lit" && m.surface.outputs.count("clearCoat") > 0; }},
      {"anisotropy",
       {std::begin(permutations::kAnisotropyModelNames), std::end(permutations::kAnisotropyModelNames)},
       [](const TierConfig& c) { return std::string(permutations::kAnisotropyModelNames[int(c.anisotropy)]); },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "anisotropy", o); },
       nullptr,
       [](const ir::Material& m) { return m.shading == "lit" && m.surface.outputs.count("anisotropy") > 0; }},
      {"ao",
       {std::begin(permutations::kAmbientOcclusionModelNames), std::end(permutations::kAmbientOcclusionModelNames)},
       [](const TierConfig& c) {
         return std::string(permutations::kAmbientOcclusionModelNames[int(c.ambientOcclusion)]);
       },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "ao", o); },
       nullptr,
       [](const ir::Material& m) { return m.shading == "lit" && m.surface.outputs.count("ambientOcclusion") > 0; }},
      {"specular_occlusion",
       {std::begin(permutations::kSpecularOcclusionModelNames), std::end(permutations::kSpecularOcclusionModelNames)},
       [](const TierConfig& c) {
         return std::string(permutations::kSpecularOcclusionModelNames[int(c.specularOcclusion)]);
       },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "specular_occlusion", o); },
       nullptr,
       [](const ir::Material& m) { return m.shading == "lit" && m.surface.outputs.count("ambientOcclusion") > 0; }},
      {"sheen",
       {std::begin(permutations::kSheenModelNames), std::end(permutations::kSheenModelNames)},
       [](const TierConfig& c) { return std::string(permutations::kSheenModelNames[int(c.sheen)]); },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "sheen", o); },
       nullptr,
       // the cloth model's sheen, or a lit material's sheen layer
       [](const ir::Material& m) {
         return m.shading == "lit" && (m.cloth || m.surface.outputs.count("sheenColor") > 0);
       }},
      {"specular_aa",
       {std::begin(permutations::kSpecularAntiAliasingModelNames),
        std::end(permutations::kSpecularAntiAliasingModelNames)},
       [](const TierConfig& c) {
         return std::string(permutations::kSpecularAntiAliasingModelNames[int(c.specularAntiAliasing)]);
       },
       [](TierConfig* c, const std::string& o) { permutations::applyOverride(c, "specular_aa", o); },
       nullptr,
       [](const ir::Material& m) { return m.shading == "lit" && m.specularAntiAliasing.has_value(); }},
  };
  return list;
}

std::vector<Configuration> configurations(const ir::Material& material, const std::vector<permutations::Tier>& tiers,
                                          bool swaps, const std::map<permutations::Tier, TierConfig>& tuned) {
  compiler::BuildOptions asShipped;
  asShipped.tunedTiers = tuned;
  std::vector<permutations::Tier> order = {permutations::Tier::Reference};
  for (permutations::Tier t : tiers)
    if (std::find(order.begin(), order.end(), t) == order.end()) order.push_back(t);
  std::vector<Configuration> out;
  for (permutations::Tier tier : order) {
    Configuration shipped;
    shipped.tier = tier;
    shipped.name = permutations::toString(tier);
    shipped.config = compiler::tierConfig(material, tier, asShipped);
    shipped.change = "as shipped";
    out.push_back(shipped);
    // The reference is the ground truth, measured only as shipped unless it was asked for.
    if (!swaps || (tier == permutations::Tier::Reference &&
                   std::find(tiers.begin(), tiers.end(), permutations::Tier::Reference) == tiers.end()))
      continue;
    for (const Axis& axis : axes()) {
      if (axis.applies && !axis.applies(shipped.config)) continue;
      if (axis.appliesToMaterial && !axis.appliesToMaterial(material)) continue;
      const std::string current = axis.get(shipped.config);
      for (const std::string& option : axis.options) {
        if (option == current) continue;
        Configuration c = shipped;
        axis.set(&c.config, option);
        if (c.config == shipped.config) continue;
        c.axis = axis.name;
        c.option = option;
        c.name = shipped.name + ":" + axis.name + "=" + option;
        c.change = std::string(axis.name) + " " + current + " → " + option;
        out.push_back(c);
      }
    }
  }
  return out;
}

std::string fileStem(const std::string& name) {
  std::string s = name;
  for (char& ch : s) {
    if (ch == ':')
      ch = '.';
    else if (ch == '=')
      ch = '-';
    else if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '.' && ch != '-')
      ch = '_';
  }
  return s;
}

}  // namespace facet::eval
