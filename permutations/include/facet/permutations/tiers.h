// Tier presets: the shading maths each GPU tier uses (docs/architecture.md, "Tiers").
#pragma once

#include <string>

#include "facet/permutations/variant_key.h"

namespace facet::permutations {

enum class SpecularModel { GgxSmith, GgxFastV, FusedHammon, Zioma, Lut };
// The material language's names of the specular models, indexed by SpecularModel
// (`tier mid { specular = zioma }`).
inline constexpr const char* kSpecularModelNames[] = {"ggx_smith", "ggx_fastv", "fused_hammon", "zioma", "lut"};
static_assert(sizeof kSpecularModelNames / sizeof *kSpecularModelNames == size_t(SpecularModel::Lut) + 1,
              "one name per SpecularModel, in its order");
// Where the diffuse ambient (and the lights' diffuse) is evaluated:
//   Pixel   per pixel, irradiance from SH in the frame block (chunks/ambient_sh.glsl)
//   Vertex  per vertex with the lights' diffuse, interpolated (Zioma 2015; forward.vert.glsl)
//   Cube    per pixel, irradiance read from the frame's irradiance cube map, SH3 tabulated by the
//           runtime (chunks/ambient_irradiance_cube.glsl): one texture read in place of the SH sum
enum class DiffuseModel { Pixel, Vertex, Cube };
// The material language's names, indexed by DiffuseModel (`tier high { diffuse = cube }`).
inline constexpr const char* kDiffuseModelNames[] = {"pixel", "vertex", "cube"};
static_assert(sizeof kDiffuseModelNames / sizeof *kDiffuseModelNames == size_t(DiffuseModel::Cube) + 1,
              "one name per DiffuseModel, in its order");
enum class ColorSpace { Linear, GammaHack };
enum class PrecisionPolicy { Highp, Mediump };
// Image-based ambient light (docs/ibl.md, "In the shaders"). Diffuse always comes from SH
// irradiance (per pixel, per vertex, or SH3 tabulated in the irradiance cube, as the diffuse axis
// says); the models differ in specular:
//   SplitSum  prefiltered environment at lod = r(2 − r)·(levels − 1), times the DFG table (Karis 2013,
//             Filament): one environment and one table sample
//   Analytic  the same environment sample, times Karis's 2014 analytic environment BRDF: no table
//   TwoMip    two samples of the environment at fixed mips (0 and the last) lerped by roughness,
//             times Zioma's 2015 environment BRDF (saturated): no variable lod, no table
//   Sampled   the ground truth for measurement (`matc eval --ground-truth`; no preset, no material
//             override): diffuse and the tier's specular lobe integrated over the environment's
//             level 0 by importance sampling, TierConfig::ambientSamples reads each
//             (chunks/ibl_sampled.glsl)
enum class AmbientModel { SplitSum, Analytic, TwoMip, Sampled };
// The clear coat of materials that write `clearCoat` (docs/material-models.md); a material without
// it compiles the same shaders whatever this says. reference and high: GgxKelemen; mid and low:
// Ambient, the form within their budget (half of high's coat cost in the mobile cost model).
//   GgxKelemen  the coat's own GGX lobe with Kelemen's visibility and Schlick's Fresnel at f0 0.04
//               for every light, and its prefiltered environment at its roughness; the base
//               lit through it × (1 − Fc(n·v)) (chunks/clear_coat_ggx_kelemen.glsl, clear_coat_ambient.glsl)
//   Ambient     the coat's environment only, over the whole base × (1 − Fc(n·v)): no lobe per light
//               (chunks/clear_coat_ambient.glsl)
//   None        the coat dropped from the shader
enum class ClearCoatModel { GgxKelemen, Ambient, None };
// The material language's names, indexed by ClearCoatModel (`tier mid { clear_coat = none }`).
inline constexpr const char* kClearCoatModelNames[] = {"ggx_kelemen", "ambient", "none"};
static_assert(sizeof kClearCoatModelNames / sizeof *kClearCoatModelNames == size_t(ClearCoatModel::None) + 1,
              "one name per ClearCoatModel, in its order");
// Anisotropy of materials that write `anisotropy` (docs/material-models.md); a material without it
// compiles the same shaders whatever this says. reference and high: GgxSmith; mid and low: None. The
// full lobe costs mid and low more than half of what it costs high (Mesa's Mali-G57), and BentIbl,
// within that half, wins back 0.1 dB of the 19 dB they lose without it on matc eval's grid
// (docs/material-models.md): the loss is the sun's highlight, which it leaves isotropic.
//   GgxSmith  anisotropic GGX D (Burley 2012) with the matching height-correlated Smith visibility
//             (Heitz 2014) for every light, in place of the tier's isotropic lobe, and the
//             environment read along a bent reflection vector (chunks/anisotropy_ggx_smith.glsl,
//             anisotropy_frame.glsl)
//   BentIbl   the bent reflection vector only: the lights keep the tier's isotropic lobe
//             (chunks/anisotropy_frame.glsl)
//   None      anisotropy dropped from the shader
enum class AnisotropyModel { GgxSmith, BentIbl, None };
// The material language's names, indexed by AnisotropyModel (`tier mid { anisotropy = none }`).
inline constexpr const char* kAnisotropyModelNames[] = {"ggx_smith", "bent_ibl", "none"};
static_assert(sizeof kAnisotropyModelNames / sizeof *kAnisotropyModelNames == size_t(AnisotropyModel::None) + 1,
              "one name per AnisotropyModel, in its order");

// The ambient occlusion of materials that write `ambientOcclusion` (docs/material-models.md,
// chunks/ambient_occlusion.glsl); a material without it compiles the same shaders whatever these say.
// reference and high: MultiBounce and Lagarde; mid and low: MultiBounce and Ao (specular occlusion
// costs them as much as it costs high for 0.5–1.1 dB; multi-bounce wins them 10–14 dB).
//   Single       the diffuse ambient × ao
//   MultiBounce  the diffuse ambient × Jimenez et al.'s 2016 multi-bounce visibility, a cubic in ao
//                and the diffuse albedo (≥ ao: light interreflected by bright occluders)
enum class AmbientOcclusionModel { Single, MultiBounce };
// The material language's names, indexed by AmbientOcclusionModel (`tier low { ao = single }`).
inline constexpr const char* kAmbientOcclusionModelNames[] = {"single", "multi_bounce"};
static_assert(sizeof kAmbientOcclusionModelNames / sizeof *kAmbientOcclusionModelNames ==
                  size_t(AmbientOcclusionModel::MultiBounce) + 1,
              "one name per AmbientOcclusionModel, in its order");
//   Ao       the specular ambient × ao, as the diffuse
//   Lagarde  the specular ambient × Lagarde & de Rousiers's 2014 specular occlusion from ao, n·v
//            and roughness (less than ao for smooth lobes at grazing views)
enum class SpecularOcclusionModel { Ao, Lagarde };
// The material language's names, indexed by SpecularOcclusionModel (`tier low { specular_occlusion = ao }`).
inline constexpr const char* kSpecularOcclusionModelNames[] = {"ao", "lagarde"};
static_assert(sizeof kSpecularOcclusionModelNames / sizeof *kSpecularOcclusionModelNames ==
                  size_t(SpecularOcclusionModel::Lagarde) + 1,
              "one name per SpecularOcclusionModel, in its order");

// The sheen of cloth materials (`shading cloth`, docs/material-models.md, chunks/shading_cloth.glsl);
// a material of another model compiles the same shaders whatever this says.
//   CharlieNeubelt  Charlie's D × Neubelt's V for every light, corrected by 1/max(1, E), and the
//                   sheen's environment (chunks/sheen_charlie_neubelt.glsl)
//   Ambient         the sheen's environment only: no lobe per light
//   None            the sheen dropped from the shader: the fabric's diffuse alone
enum class SheenModel { CharlieNeubelt, Ambient, None };
// The material language's names, indexed by SheenModel (`tier low { sheen = ambient }`).
inline constexpr const char* kSheenModelNames[] = {"charlie_neubelt", "ambient", "none"};
static_assert(sizeof kSheenModelNames / sizeof *kSheenModelNames == size_t(SheenModel::None) + 1,
              "one name per SheenModel, in its order");

// Specular anti-aliasing of materials that ask for it (`specularAntiAliasing { }`,
// docs/material-models.md); a material without it compiles the same shaders whatever this says.
// reference and high: Projected; mid and low: None (docs/material-models.md has the measurements).
//   Projected  Tokuyoshi and Kaplanyan's 2019 projected-space NDF filtering: the kernel's α² from the
//              screen-space derivatives of the shading normal, added to the lobe's
//              (chunks/specular_antialiasing.glsl)
//   None       dropped from the shader
enum class SpecularAntiAliasingModel { Projected, None };
// The material language's names, indexed by SpecularAntiAliasingModel (`tier low { specular_aa = none }`).
inline constexpr const char* kSpecularAntiAliasingModelNames[] = {"projected", "none"};
static_assert(sizeof kSpecularAntiAliasingModelNames / sizeof *kSpecularAntiAliasingModelNames ==
                  size_t(SpecularAntiAliasingModel::None) + 1,
              "one name per SpecularAntiAliasingModel, in its order");

// How a shadow receiver filters the sun's atlas (chunks/shadow_sun.glsl, docs/shadows.md): a 3×3
// tent from 4 bilinear compare taps, or one compare tap (bilinear 2×2 where the device filters
// depth).
enum class ShadowFilter { Tent3x3, OneTap };

struct TierConfig {
  SpecularModel specular = SpecularModel::GgxSmith;
  DiffuseModel diffuse = DiffuseModel::Pixel;
  ColorSpace colorSpace = ColorSpace::Linear;
  PrecisionPolicy precision = PrecisionPolicy::Mediump;
  AmbientModel ambient = AmbientModel::SplitSum;
  // SH irradiance bands: 3 (9 coefficients), 2 (4) or 5 (l = 0..4: 18, band 3 being 0); DiffuseModel::Cube
  // reads SH3 tabulated whatever this says
  int shBands = 3;
  bool energyCompensation = false;  // Filament's multiple-scattering factor on all specular (SplitSum only)
  ClearCoatModel clearCoat = ClearCoatModel::GgxKelemen;
  AnisotropyModel anisotropy = AnisotropyModel::GgxSmith;
  ShadowFilter shadowFilter = ShadowFilter::Tent3x3;
  int ambientSamples = 0;  // AmbientModel::Sampled: points per integral and pixel
  // The environment read along the lobe's dominant direction instead of the mirror direction
  // (chunks/shading_ambient.glsl, specular_dominant_direction); prefiltered ambient models only.
  bool dominantDirection = false;
  AmbientOcclusionModel ambientOcclusion = AmbientOcclusionModel::MultiBounce;
  SpecularOcclusionModel specularOcclusion = SpecularOcclusionModel::Lagarde;
  SheenModel sheen = SheenModel::CharlieNeubelt;
  SpecularAntiAliasingModel specularAntiAliasing = SpecularAntiAliasingModel::Projected;
  bool operator==(const TierConfig&) const = default;
};

// reference: highp GGX/Smith/Schlick, the ground truth every other tier is measured against;
//            split-sum IBL + SH3, energy compensation on direct and IBL specular.
// high:      the same maths in mediump with the fp16 clamps of chunks/precision.glsl.
// mid:       GGX D × Hammon's V fused into one division, F = f0 (chunks/specular_fused_hammon.glsl:
//            38.3 dB on brushed_gold against 30.8 with Zioma's fused V·F, at the same Mali cycles),
//            per-vertex diffuse and SH3, mediump;
//            split-sum IBL with energy compensation (+13 dB on the spheres scene and rough gold
//            18.9 → 28.4 dB against Karis's analytic fit, for +0.04 cycles).
// low:       LUT specular (one texture read, no D/V/F) scaled by the environment BRDF, per-vertex
//            diffuse and SH2, linear, mediump; split-sum IBL with energy compensation (against the
//            two-mip lerp, +7 dB on the spheres scene). Linear rather than the gamma hack: better
//            on every example material and cheaper (docs/eval.md); ColorSpace::GammaHack remains
//            an option matc eval measures.
// docs/specular-tiers.md has the measurements.
TierConfig preset(Tier tier);

// Replaces one choice of a preset by name (axis "specular" | "diffuse" | "clear_coat" | "anisotropy" | "ao" |
// "specular_occlusion" | "sheen" | "specular_aa", option as in the material language). Returns false for names it does
// not know.
bool applyOverride(TierConfig* config, const std::string& axis, const std::string& option);

// e.g. "ggx_smith, pixel diffuse, linear, mediump, split_sum + sh3"
std::string describe(const TierConfig& config);

}  // namespace facet::permutations
