// Assembly: template + chunks + the material's surface program -> complete GLSL per stage.
//
// Two flavours of the same code: GLSL ES 3.00 for OpenGL ES (what the GL runtime and phones
// run), and GLSL ES 3.10 with Vulkan layout qualifiers, the input to glslang for SPIR-V and
// hence MSL. Only the prologue and the interface declarations differ; the bodies are identical.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/param_layout.h"
#include "facet/compiler/preshader.h"
#include "facet/ir/emit_glsl.h"
#include "facet/ir/module.h"
#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"

namespace facet::compiler {

enum class Flavour { GlslEs300, Vulkan };

struct StageSources {
  std::string vertex;
  std::string fragment;
  // 1-based line of the fragment text where the surface program's body starts (0: not present);
  // line k of SurfaceGlsl::body is line fragmentSurfaceLine + k.
  uint32_t fragmentSurfaceLine = 0;
  // The templates/ and chunks/ files (glslLibrary() names) both stages were assembled from: what a
  // build system must watch (matc compile --depfile).
  std::set<std::string> libraryFiles;
};

struct AssemblyInput {
  const ir::Material& material;
  const ir::SurfaceGlsl& surface;
  const ParamLayout& params;
  permutations::VariantKey key;
  permutations::TierConfig tier;  // the maths this variant's tier uses
  std::string compilerVersion;
  // Set when the variant reads preshaded inputs (compiler/preshader.h): the block declares the
  // derived members after the parameters and FACET_PRESHADED_* is defined per input.
  const PreshadeLayout* preshade = nullptr;
};

// Names the compiler's other stages use, from the shader interface (shader_abi.h owns them).
inline constexpr const char* kSpecularLutSamplerName = abi::kSpecularLutName;
inline constexpr uint32_t kEnvironmentLevels = abi::kEnvironmentLevels;

// Whether a variant's fragment stage samples the prefiltered environment (every lit variant) and
// the DFG table (lit variants of split-sum tiers).
bool samplesEnvironment(const AssemblyInput& input);
bool samplesDfgLut(const AssemblyInput& input);
// Shadow receivers (VariantKey::receivesShadow: the sun's, a spot's) read ShadowUniforms and the
// shadow atlas.
bool samplesShadowAtlas(const AssemblyInput& input);
// Whether a tier's lit variants read the irradiance cube (diffuse `cube`, unless the tier samples
// the environment for its ambient): only packages with one list its Metal slot, so every other
// package keeps its bytes and packages built before the cube keep loading.
bool samplesIrradianceCube(const permutations::TierConfig& tier, const std::string& shading);

// Whether the variant's fragment stage samples the specular table (a lit variant with a light
// whose tier uses `lut` specular): the package must then carry the table (compiler/specular_lut.h).
bool samplesSpecularLut(const AssemblyInput& input);

// Fails only on a defect of the compiler itself (a template including a missing chunk);
// the message says which.
bool assemble(const AssemblyInput& input, Flavour flavour, StageSources* out, std::string* error);

// A fixed block of shader_abi.h as GLSL: std140, with its set and binding on the Vulkan flavour
// (GLSL ES 3.00 has none: the runtime binds blocks by name). The post domain declares its block so.
std::string uniformBlockDeclaration(Flavour flavour, const abi::BlockDesc& block);

// One specular option's lobe on its own: `specular_lobe(...)` and the chunks it needs, includes
// resolved (matc eval's BRDF-domain sweep runs it in a compute shader). The LUT lobe reads the
// sampler `facet_specularLut` (kSpecularLutSamplerName), which the caller declares.
bool specularLobeSource(permutations::SpecularModel model, std::string* out, std::string* error);

// The named chunks (e.g. "clear_coat_ggx_kelemen.glsl") in order, includes resolved, without a
// material: for the lobes of the material models, whose chunks read a MaterialInputs the caller
// declares first (matc eval's sweep of the clear coat, anisotropy and sheen lobes).
bool chunkSource(const std::vector<std::string>& names, std::string* out, std::string* error);

}  // namespace facet::compiler
