// Tier presets: the shading maths each GPU tier uses (DESIGN.md, "Tiers").
#pragma once

#include <string>

#include "facet/permutations/variant_key.h"

namespace facet::permutations {

enum class SpecularModel { GgxSmith, GgxFastV, Zioma, Lut };
enum class DiffuseModel { Pixel, Vertex };
enum class ColorSpace { Linear, GammaHack };
enum class PrecisionPolicy { Highp, Mediump };

struct TierConfig {
  SpecularModel specular = SpecularModel::GgxSmith;
  DiffuseModel diffuse = DiffuseModel::Pixel;
  ColorSpace colorSpace = ColorSpace::Linear;
  PrecisionPolicy precision = PrecisionPolicy::Mediump;
  bool operator==(const TierConfig&) const = default;
};

// reference: highp GGX/Smith/Schlick, the ground truth every other tier is measured against.
// high:      the same maths in mediump with the fp16 clamps of chunks/precision.glsl.
// mid:       Facet's Zioma specular (one division), per-vertex diffuse, mediump.
// low:       LUT specular (one texture read, no D/V/F), per-vertex diffuse, the gamma hack
//            (colours stay sRGB-encoded, lighting on encoded values), mediump.
TierConfig preset(Tier tier);

// Replaces one choice of a preset by name (axis "specular" | "diffuse", option as in the
// material language). Returns false for names it does not know.
bool applyOverride(TierConfig* config, const std::string& axis, const std::string& option);

// e.g. "ggx_smith, pixel diffuse, linear, mediump"
std::string describe(const TierConfig& config);

}  // namespace facet::permutations
