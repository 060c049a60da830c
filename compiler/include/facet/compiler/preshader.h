// The preshader (Unreal's term): the shading inputs that depend only on parameters leave the
// fragment stage: the standard model's (diffuse colour, f0, clamped perceptual roughness and
// α = r², chunks/shading_standard.glsl, and the roughness's terms the lit chunks read: the
// environment's lod, 2^12 α and the Zioma lobe's 4π (p α + q)) and the other models' terms of
// their own inputs (the clear coat's strength, α_c and environment lod; anisotropy's k, (α_t, α_b)
// and bend; the sheen's colour, r_s, α_s and environment lod: docs/material-models.md). The
// compiler appends them to "MaterialParams" as members after the parameters and writes, per
// variant, a program (package::PreshaderProgram) that the runtime runs on the CPU whenever an
// instance's parameters change. The program holds the surface program's expressions for the
// inputs and the model's derivations as plain ops, so the runtime needs no shading knowledge.
// docs/package-format.md ("PRSH") and docs/eval.md (what it saves).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/compiler/param_layout.h"
#include "facet/ir/module.h"
#include "facet/package/package.h"
#include "facet/permutations/tiers.h"

namespace facet::compiler {

// A derived member of the parameter block: GLSL type and name, std140 offset.
struct PreshadedMember {
  const char* type;  // "vec3", "vec2" or "float"
  const char* name;  // e.g. "facet_f0"
  uint32_t offset;
  uint32_t components;
};

// Which inputs a material's lit variants read preshaded (material-wide: the block layout is one
// for every variant) and where they live. Each input is preshaded when every surface output it
// is derived from is uniform-only (ir::isUniformOnly) and made of ops the program has (constants,
// float parameters, swizzles, + − ×, negation, clamp to constants); otherwise it stays per pixel.
struct PreshadeLayout {
  bool diffuseColor = false;  // FACET_PRESHADED_DIFFUSE_COLOR: from baseColor, metallic
  bool f0 = false;            // FACET_PRESHADED_F0: from baseColor, metallic, reflectance
  // FACET_PRESHADED_ROUGHNESS: perceptual roughness, α, the environment's lod, 2^12 α and Zioma's
  // 4π (p α + q), from roughness
  bool roughness = false;
  bool clearCoat = false;  // FACET_PRESHADED_CLEAR_COAT: the coat's strength, from clearCoat
  // FACET_PRESHADED_CLEAR_COAT_ROUGHNESS: α_c = r_c² and the coat's environment lod, from clearCoatRoughness
  bool clearCoatRoughness = false;
  // FACET_PRESHADED_ANISOTROPY: k, (α_t, α_b) and the reflection's bend, from anisotropy and roughness
  bool anisotropy = false;
  bool sheenColor = false;  // FACET_PRESHADED_SHEEN_COLOR: the sheen's linear colour, from sheenColor
  // FACET_PRESHADED_SHEEN_ROUGHNESS: r_s, α_s = r_s² and the sheen's environment lod, from
  // sheenRoughness (a sheen layer); a cloth material's r_s is its roughness: the lod alone
  bool sheenRoughness = false;
  std::vector<PreshadedMember> members;
  uint32_t blockSize = 0;  // parameters and derived members, std140; 0: nothing preshaded
  bool any() const { return blockSize != 0; }
};

// Unlit materials and materials with no preshadable input get an empty layout.
PreshadeLayout planPreshade(const ir::Material& material, const ParamLayout& params);

// The program of one variant of `tier` (its colour space picks f0's form). Empty when the layout
// preshades nothing.
std::vector<package::PreshaderOp> preshaderProgram(const ir::Material& material, const ParamLayout& params,
                                                   const PreshadeLayout& layout, const permutations::TierConfig& tier);

// MIN_PERCEPTUAL_ROUGHNESS as chunks/precision.glsl defines it (the one place it is written).
float minPerceptualRoughness();

// ANISOTROPY_ALPHA_MIN and ANISOTROPY_BEND_MAX as chunks/anisotropy_frame.glsl defines them (the
// one place each is written).
float anisotropyAlphaMin();
float anisotropyBendMax();

}  // namespace facet::compiler
