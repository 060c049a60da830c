#include "facet/compiler/assemble.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/glsl_library.h"

namespace facet::compiler {
namespace {

static_assert(permutations::kMaxPointLights == abi::kMaxPunctualLights,
              "a variant's punctual lights are read from the frame block's fixed array");

// An optional vertex input (shader_abi.h's attribute at `location`: its name a vertex.* attribute,
// or "tangent", needed by the normal output) and the varying that carries it to the fragment
// stage. Precision follows the tiers' policy (docs/architecture.md, "Tiers"): positions and UVs
// highp always; colours and
// directions at the tier's precision.
struct OptionalInput {
  uint32_t location;
  const char* varyingType;  // with "highp " when it must stay highp whatever the tier
  const char* varying;
  std::string_view name() const { return abi::vertexAttribute(location).name; }
};

const OptionalInput kOptionalInputs[] = {
    {abi::kAttribUv0, "highp vec2", "v_uv0"},
    {abi::kAttribUv1, "highp vec2", "v_uv1"},
    {abi::kAttribColor, "vec4", "v_color"},
    {abi::kAttribTangent, "vec4", "v_tangent"},
};

// A sun-shadow receiver (VariantKey shadowCascades; requestKey gives it lit dir1 variants only).
bool receivesShadow(const AssemblyInput& in) {
  return in.key.shadowCascades > 0 && in.key.directionalLight && in.material.shading == "lit";
}

// A spot-shadow receiver (VariantKey spotShadows): light slot 0 is the casting spot
// (docs/shadows.md, "Spot shadows"); requestKey gives it lit variants with point lights only.
bool receivesSpotShadow(const AssemblyInput& in) {
  return in.key.spotShadows > 0 && in.key.pointLights > 0 && in.material.shading == "lit";
}

// Either receiver binds the shadow block and samples the atlas.
bool readsShadowAtlas(const AssemblyInput& in) { return receivesShadow(in) || receivesSpotShadow(in); }

bool vertexDiffuse(const AssemblyInput& in) {
  return in.tier.diffuse == permutations::DiffuseModel::Vertex && in.material.shading == "lit";
}

// The `cube` diffuse reads the frame's irradiance cube per pixel; the sampled ground truth
// integrates its own diffuse instead.
bool cubeDiffuse(const AssemblyInput& in) { return samplesIrradianceCube(in.tier, in.material.shading); }

// The tangent frame is needed only to apply a tangent-space normal, and only lit shading reads it.
bool usesNormalOutput(const AssemblyInput& in) {
  return in.material.shading == "lit" && in.material.surface.outputs.count("normal") > 0;
}

// A material writing `clearCoat` has a coat (lit only: the checker drops it from unlit ones); the
// tier says in which form, or drops it (permutations::ClearCoatModel).
bool writesClearCoat(const AssemblyInput& in) {
  return in.material.shading == "lit" && in.material.surface.outputs.count("clearCoat") > 0;
}

bool shadesClearCoat(const AssemblyInput& in) {
  return writesClearCoat(in) && in.tier.clearCoat != permutations::ClearCoatModel::None;
}

bool usesClearCoatNormal(const AssemblyInput& in) {
  return shadesClearCoat(in) && in.material.surface.outputs.count("clearCoatNormal") > 0;
}

// A material writing `anisotropy` is anisotropic (lit only); the tier says in which form, or drops
// it (permutations::AnisotropyModel).
bool writesAnisotropy(const AssemblyInput& in) {
  return in.material.shading == "lit" && in.material.surface.outputs.count("anisotropy") > 0;
}

bool shadesAnisotropy(const AssemblyInput& in) {
  return writesAnisotropy(in) && in.tier.anisotropy != permutations::AnisotropyModel::None;
}

// The anisotropic GGX lobe replaces the tier's isotropic one for every light
// (anisotropy_ggx_smith.glsl, FACET_ANISOTROPY_LOBE).
bool shadesAnisotropicLobe(const AssemblyInput& in) {
  return writesAnisotropy(in) && in.tier.anisotropy == permutations::AnisotropyModel::GgxSmith;
}

// A material asking for specular anti-aliasing (lit or cloth: the checker rejects it in unlit ones);
// the tier says in which form, or drops it (permutations::SpecularAntiAliasingModel).
bool shadesSpecularAntiAliasing(const AssemblyInput& in) {
  return in.material.shading == "lit" && in.material.specularAntiAliasing &&
         in.tier.specularAntiAliasing != permutations::SpecularAntiAliasingModel::None;
}

// `shading cloth`: a lit material shaded by the cloth model (chunks/shading_cloth.glsl).
bool shadesCloth(const AssemblyInput& in) { return in.material.shading == "lit" && in.material.cloth; }

// A lit (standard-model) material writing sheenColor has a sheen layer over its base
// (chunks/sheen_layer.glsl); the tier's `sheen` axis says in which form, or drops it.
bool writesSheenLayer(const AssemblyInput& in) {
  return in.material.shading == "lit" && !in.material.cloth && in.material.surface.outputs.count("sheenColor") > 0;
}

bool shadesSheenLayer(const AssemblyInput& in) {
  return writesSheenLayer(in) && in.tier.sheen != permutations::SheenModel::None;
}

// Tangent-space outputs, and anisotropy's direction (the mesh's tangent by default), need the
// per-pixel tangent frame (normal_mapping.glsl).
bool needsTangentFrame(const AssemblyInput& in) {
  return usesNormalOutput(in) || usesClearCoatNormal(in) || shadesAnisotropy(in);
}

// The world position reaches the fragment stage only where something there reads it: point
// lights, or a surface program reading vertex.worldPosition. Otherwise the vertex stage sends the
// vector to the eye instead, camera − position: affine in the position, so its interpolation is
// exact, and the fragment stage saves the highp subtraction (3 FMA slots per pixel).
bool worldPositionVarying(const AssemblyInput& in) {
  return in.key.pointLights > 0 || in.surface.attributes.count("worldPosition") > 0;
}

// The vector to the eye (the v_toEye varying) is interpolated and normalized at the tier's
// precision where no lobe needs its fp32 bits: mediump saves 3 of the varying pipe's 16-bit
// channels per pixel and the normalize's conversions (docs/fp16-emulation.md, "The view
// vector"). The lobes that sum the half vector in highp (SPECULAR_HALF_VECTOR_HIGHP in
// specular_ggx_smith.glsl, specular_ggx_fastv.glsl, anisotropy_ggx_smith.glsl: at a grazing glint
// v + l cancels, chunks/shading_standard.glsl) keep it highp, and so does a world-position
// varying (a binary16 position 1 km away has 0.5 m steps). The cloth model reads none of those
// lobes, whatever the tier's specular: its sheen sums the half vector at the tier's precision.
bool viewVectorMediump(const AssemblyInput& in) {
  if (worldPositionVarying(in) || in.tier.precision != permutations::PrecisionPolicy::Mediump) return false;
  if (in.material.shading != "lit") return true;
  const bool highpHalfLobe = in.tier.specular == permutations::SpecularModel::GgxSmith ||
                             in.tier.specular == permutations::SpecularModel::GgxFastV || shadesAnisotropicLobe(in);
  return !highpHalfLobe || shadesCloth(in);
}

// The Zioma lobe alone over the base takes the half vector scaled by GGX_D_SCALE = 2^6, folded into
// its normalization (FACET_HALF_VECTOR_SCALED: chunks/shading_standard.glsl, ggx_denominator.glsl).
// Every reader of h and n·h in such a variant is that lobe's GGX denominator; a clear coat's lobe,
// a sheen layer and the anisotropic lobe read them unscaled, and the cloth model has no such lobe.
bool halfVectorScaled(const AssemblyInput& in) {
  const bool clearCoatLobe = writesClearCoat(in) && in.tier.clearCoat == permutations::ClearCoatModel::GgxKelemen;
  return in.material.shading == "lit" && !shadesCloth(in) && in.tier.specular == permutations::SpecularModel::Zioma &&
         !clearCoatLobe && !shadesSheenLayer(in) && !shadesAnisotropicLobe(in);
}

bool needs(const AssemblyInput& in, const OptionalInput& v) {
  if (v.location == abi::kAttribTangent) return needsTangentFrame(in);
  return in.surface.attributes.count(std::string(v.name())) > 0;
}

// Declarations printed from shader_abi.h's tables, the one place the numbers are written.
// GLSL ES 3.00 has no layout(binding): the runtime binds blocks and samplers by name there.
std::string blockLayout(Flavour flavour, const abi::BlockDesc& block) {
  if (flavour == Flavour::GlslEs300) return "layout(std140)";
  return "layout(std140, set = " + std::to_string(block.set) + ", binding = " + std::to_string(block.binding) + ")";
}

std::string members(std::span<const abi::MemberDesc> list) {
  std::string s;
  for (const abi::MemberDesc& m : list) {
    s += "    " + std::string(m.type) + " " + std::string(m.name);
    if (m.arraySize != 0) s += "[" + std::to_string(m.arraySize) + "]";
    s += ";\n";
  }
  return s;
}

std::string fixedBlock(Flavour flavour, const abi::BlockDesc& block) {
  return blockLayout(flavour, block) + " uniform " + std::string(block.name) + " {\n" + members(block.members) + "} " +
         std::string(block.instance) + ";\n";
}

std::string samplerLayout(Flavour flavour, uint32_t set, uint32_t binding) {
  if (flavour != Flavour::Vulkan) return "";
  return "layout(set = " + std::to_string(set) + ", binding = " + std::to_string(binding) + ") ";
}

std::string frameSampler(Flavour flavour, const abi::SamplerDesc& sampler, const char* precision) {
  return samplerLayout(flavour, sampler.set, sampler.binding) + "uniform " + precision +
         (sampler.cube ? " samplerCube " : " sampler2D ") + std::string(sampler.name) + ";\n";
}

// The per-frame block, identical text in both stages (GLSL ES requires blocks shared between
// stages to match member for member, precision included). The per-object block is the vertex
// stage's alone: no fragment chunk reads the transforms or the dequantisation, and its text
// would only lengthen every fragment shader a driver parses.
// A tier with SH band 4 (shBands 5) declares the sh array's band-4 entries too; every other
// tier stops after SH3's, so its text and uniform count do not depend on the option.
std::string frameBlock(Flavour flavour, const permutations::TierConfig& tier) {
  std::vector<abi::MemberDesc> list(std::begin(abi::kFrameMembers), std::end(abi::kFrameMembers));
  if (tier.shBands > 3) list.back().arraySize = abi::kShFrameCoefficients;
  const abi::BlockDesc block{
      abi::kFrameBlock.name,      abi::kFrameBlock.instance, abi::kFrameBlock.set, abi::kFrameBlock.binding, list,
      abi::kFrameBlock.std140Size};
  return "struct " + std::string(abi::kPunctualLightStruct.name) + " {\n" + members(abi::kPunctualLightStruct.members) +
         "};\n" + fixedBlock(flavour, block);
}

// Parameters are read at the tier's precision: a block member needs an explicit qualifier (the
// block could be declared in a stage with another default), and it is the tier's own.
std::string materialBlock(Flavour flavour, const ir::Material& material, const ParamLayout& layout,
                          const PreshadeLayout* preshade, const char* precision) {
  if (layout.blockSize == 0 && !preshade) return "";
  std::string s = "// std140 offsets as recorded in the package: ";
  std::string sep;
  for (const ParamSlot& slot : layout.slots) {
    if (slot.size == 0) continue;
    s += sep + slot.name + "@" + std::to_string(slot.offset);
    sep = ", ";
  }
  s += "\n" + blockLayout(flavour, abi::kMaterialBlock) + " uniform " + std::string(abi::kMaterialBlock.name) + " {\n";
  for (const ir::Param& p : material.params) {
    if (!p.used || p.type == ir::Type::Texture2D) continue;
    // A declared range beyond fp16's 65504 keeps the member in fp32 (emit_glsl does the same
    // for values computed from it).
    bool wide = (p.rangeMin && std::abs(*p.rangeMin) > 65504.0) || (p.rangeMax && std::abs(*p.rangeMax) > 65504.0);
    std::string qualifier = p.type == ir::Type::Bool ? "" : std::string(wide ? "highp" : precision) + " ";
    s += "    " + qualifier + ir::glslName(p.type) + " " + p.name + ";\n";
  }
  if (preshade) {
    // The preshader's derived inputs (compiler/preshader.h), written by the runtime on the CPU,
    // start at the parameter block's size: floats pad the parameters' last vec4 up to it (a float
    // member would otherwise pack into it).
    uint32_t end = 0;
    for (const ParamSlot& slot : layout.slots) end = std::max(end, slot.offset + slot.size);
    for (uint32_t at = end; at < layout.blockSize; at += 4)
      s += "    " + std::string(precision) + " float facet_pad" + std::to_string(at) + ";\n";
    for (const PreshadedMember& m : preshade->members)
      s += "    " + std::string(precision) + " " + m.type + " " + m.name + ";  // @" + std::to_string(m.offset) +
           ", preshaded\n";
  }
  return s + "} " + std::string(abi::kMaterialBlock.instance) + ";\n";
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// One sampler uniform per texture the material reads, at its slot's binding (shader_abi.h
// materialTextureBinding); GLES binds by name, kMaterialSamplerPrefix + the parameter's.
std::string materialSamplers(Flavour flavour, const ParamLayout& layout, const char* precision) {
  std::string s;
  for (const ParamSlot& slot : layout.slots) {
    if (slot.textureSlot < 0) continue;
    s += samplerLayout(flavour, abi::kTextureSet, abi::materialTextureBinding(uint32_t(slot.textureSlot)));
    s += "uniform " + std::string(precision) + " sampler2D " + abi::kMaterialSamplerPrefix + slot.name + ";\n";
  }
  return s;
}

std::string prologue(const AssemblyInput& in, Flavour flavour, const char* stage, const char* floatPrecision) {
  std::string s = flavour == Flavour::GlslEs300 ? "#version 300 es\n" : "#version 310 es\n";
  s += "// Material '" + in.material.name + "', variant " + in.key.toString() + ", " + stage + " stage, " +
       (flavour == Flavour::GlslEs300 ? "GLSL ES 3.00 (OpenGL ES)" : "Vulkan flavour (input to SPIR-V and MSL)") +
       ".\n// Generated by " + in.compilerVersion + ". Do not edit: change the material and recompile.\n";
  s += std::string("precision ") + floatPrecision + " float;\nprecision highp int;\n";
  s += "// Tier " + std::string(permutations::toString(in.key.tier)) + ": " + permutations::describe(in.tier) + ".\n";
  for (const OptionalInput& v : kOptionalInputs)
    if (needs(in, v)) s += "#define FACET_VARYING_" + upper(std::string(v.name())) + " 1\n";
  if (usesNormalOutput(in)) s += "#define FACET_MATERIAL_NORMAL 1\n";
  // FACET_TO_EYE: the unnormalised vector from the surface to the eye, for the fragment templates
  // to normalize, from whichever of the two varyings the variant has (worldPositionVarying); highp,
  // or mediump and scaled into binary16's range (viewVectorMediump, templates/forward.vert.glsl).
  if (worldPositionVarying(in))
    s += "#define FACET_VARYING_WORLD_POSITION 1\n#define FACET_TO_EYE (frame.cameraPosition.xyz - v_worldPosition)\n";
  else
    s += "#define FACET_TO_EYE v_toEye\n";
  if (viewVectorMediump(in)) s += "#define FACET_VIEW_VECTOR_MEDIUMP 1\n";
  if (halfVectorScaled(in)) s += "#define FACET_HALF_VECTOR_SCALED 1\n";
  if (in.material.shading == "lit" && in.material.surface.outputs.count("ambientOcclusion") > 0) {
    s += "#define FACET_MATERIAL_AMBIENT_OCCLUSION 1\n";
    s += "// Ambient occlusion: " +
         std::string(permutations::kAmbientOcclusionModelNames[int(in.tier.ambientOcclusion)]) + " on the diffuse, " +
         permutations::kSpecularOcclusionModelNames[int(in.tier.specularOcclusion)] +
         " on the specular (docs/material-models.md).\n";
    if (in.tier.ambientOcclusion == permutations::AmbientOcclusionModel::MultiBounce)
      s += "#define FACET_AO_MULTI_BOUNCE 1\n";
    if (in.tier.specularOcclusion == permutations::SpecularOcclusionModel::Lagarde)
      s += "#define FACET_SPECULAR_OCCLUSION_LAGARDE 1\n";
  }
  if (writesClearCoat(in)) {
    const char* forms[] = {"its GGX/Kelemen lobe per light and its environment",
                           "its environment over the lit base, no lobe per light", "dropped in this tier"};
    s += "// Clear coat: " + std::string(permutations::kClearCoatModelNames[int(in.tier.clearCoat)]) + ", " +
         forms[int(in.tier.clearCoat)] + " (docs/material-models.md).\n";
    // FACET_CLEAR_COAT_LOBE: a lobe per light (the base under the coat is attenuated before any light).
    if (in.tier.clearCoat == permutations::ClearCoatModel::GgxKelemen)
      s += "#define FACET_CLEAR_COAT_GGX_KELEMEN 1\n#define FACET_CLEAR_COAT_LOBE 1\n";
    if (in.tier.clearCoat == permutations::ClearCoatModel::Ambient) s += "#define FACET_CLEAR_COAT_AMBIENT 1\n";
    if (usesClearCoatNormal(in)) s += "#define FACET_MATERIAL_CLEAR_COAT_NORMAL 1\n";
  }
  if (writesAnisotropy(in)) {
    const char* forms[] = {"its GGX/Smith lobe per light and the bent reflection vector",
                           "the bent reflection vector, the tier's isotropic lobe per light", "dropped in this tier"};
    s += "// Anisotropy: " + std::string(permutations::kAnisotropyModelNames[int(in.tier.anisotropy)]) + ", " +
         forms[int(in.tier.anisotropy)] + " (docs/material-models.md).\n";
    if (shadesAnisotropicLobe(in)) s += "#define FACET_ANISOTROPY_LOBE 1\n#define FACET_ANISOTROPY 1\n";
    if (in.tier.anisotropy == permutations::AnisotropyModel::BentIbl) s += "#define FACET_ANISOTROPY 1\n";
    // Without it the direction is the mesh's tangent, with no frame to apply (anisotropy_frame.glsl).
    if (shadesAnisotropy(in) && in.material.surface.outputs.count("anisotropyDirection") > 0)
      s += "#define FACET_MATERIAL_ANISOTROPY_DIRECTION 1\n";
  }
  if (shadesCloth(in)) {
    const char* forms[] = {"Charlie's D with Neubelt's V per light and its environment",
                           "its environment only, no lobe per light", "dropped in this tier"};
    s += "// Cloth: sheen " + std::string(permutations::kSheenModelNames[int(in.tier.sheen)]) + ", " +
         forms[int(in.tier.sheen)] + " (docs/material-models.md).\n#define FACET_SHADING_CLOTH 1\n";
    if (in.tier.sheen == permutations::SheenModel::CharlieNeubelt) s += "#define FACET_SHEEN_LOBE 1\n";
    if (in.tier.sheen != permutations::SheenModel::None) s += "#define FACET_SHEEN_AMBIENT 1\n";
    if (in.material.surface.outputs.count("sheenColor") > 0) s += "#define FACET_MATERIAL_SHEEN_COLOR 1\n";
    if (in.material.surface.outputs.count("subsurfaceColor") > 0) s += "#define FACET_MATERIAL_SUBSURFACE_COLOR 1\n";
  }
  // Fragment stage only: the vertex stage reads no roughness.
  if (in.material.shading == "lit" && in.material.specularAntiAliasing && std::string_view(stage) == "fragment") {
    const ir::Material::SpecularAntiAliasing& aa = *in.material.specularAntiAliasing;
    const bool shaded = shadesSpecularAntiAliasing(in);
    s += "// Specular anti-aliasing: " +
         std::string(permutations::kSpecularAntiAliasingModelNames[int(in.tier.specularAntiAliasing)]) +
         (shaded ? ", the lobe widened by the shading normal's screen-space variance" : ", dropped in this tier") +
         " (docs/material-models.md).\n";
    if (shaded) {
      s += "#define FACET_SPECULAR_AA 1\n#define FACET_SPECULAR_AA_VARIANCE " +
           ir::glslConstant(ir::Type::Float, {aa.variance}) + "\n#define FACET_SPECULAR_AA_THRESHOLD " +
           ir::glslConstant(ir::Type::Float, {aa.threshold}) + "\n";
    }
  }
  if (writesSheenLayer(in)) {
    const char* forms[] = {"Charlie's D with Neubelt's V per light and its environment",
                           "its environment over the lit base, no lobe per light", "dropped in this tier"};
    s += "// Sheen layer: " + std::string(permutations::kSheenModelNames[int(in.tier.sheen)]) + ", " +
         forms[int(in.tier.sheen)] + " (docs/material-models.md).\n";
    if (in.tier.sheen == permutations::SheenModel::CharlieNeubelt) s += "#define FACET_SHEEN_LOBE 1\n";
    if (shadesSheenLayer(in))
      s += "#define FACET_SHEEN_AMBIENT 1\n#define FACET_SHEEN_LAYER 1\n#define FACET_MATERIAL_SHEEN_COLOR 1\n";
  }
  if (in.key.directionalLight) s += "#define FACET_DIRECTIONAL_LIGHT 1\n";
  s += "#define FACET_POINT_LIGHTS " + std::to_string(in.key.pointLights) + "\n";
  if (receivesShadow(in)) s += "#define FACET_SHADOW_CASCADES " + std::to_string(in.key.shadowCascades) + "\n";
  if (receivesSpotShadow(in)) s += "#define FACET_SPOT_SHADOW 1\n";
  if (readsShadowAtlas(in) && in.tier.shadowFilter == permutations::ShadowFilter::Tent3x3)
    s += "#define FACET_SHADOW_FILTER_TENT 1\n";
  if (in.material.blending != "opaque") s += "#define FACET_BLENDING_" + upper(in.material.blending) + " 1\n";
  if (in.material.blending == "masked")
    s += "#define FACET_ALPHA_CUTOFF " + ir::glslConstant(ir::Type::Float, {in.material.alphaCutoff}) + "\n";
  if (vertexDiffuse(in)) s += "#define FACET_VERTEX_DIFFUSE 1\n";
  if (cubeDiffuse(in)) s += "#define FACET_IRRADIANCE_CUBE 1\n";
  if (in.tier.precision == permutations::PrecisionPolicy::Highp) s += "#define FACET_PRECISION_HIGHP 1\n";
  if (in.tier.colorSpace == permutations::ColorSpace::GammaHack) s += "#define FACET_GAMMA_HACK 1\n";
  if (in.preshade) {
    if (in.preshade->diffuseColor) s += "#define FACET_PRESHADED_DIFFUSE_COLOR 1\n";
    if (in.preshade->f0) s += "#define FACET_PRESHADED_F0 1\n";
    if (in.preshade->roughness) s += "#define FACET_PRESHADED_ROUGHNESS 1\n";
    if (in.preshade->clearCoat) s += "#define FACET_PRESHADED_CLEAR_COAT 1\n";
    if (in.preshade->clearCoatRoughness) s += "#define FACET_PRESHADED_CLEAR_COAT_ROUGHNESS 1\n";
    if (in.preshade->anisotropy) s += "#define FACET_PRESHADED_ANISOTROPY 1\n";
    if (in.preshade->sheenColor) s += "#define FACET_PRESHADED_SHEEN_COLOR 1\n";
    if (in.preshade->sheenRoughness) s += "#define FACET_PRESHADED_SHEEN_ROUGHNESS 1\n";
  }
  if (in.material.shading == "lit") {
    // Image-based ambient (docs/ibl.md, "In the shaders"): the tier's specular model, SH bands for
    // the diffuse part (evaluated in the vertex stage with FACET_VERTEX_DIFFUSE).
    switch (in.tier.ambient) {
      case permutations::AmbientModel::SplitSum: s += "#define FACET_IBL_SPLIT_SUM 1\n"; break;
      case permutations::AmbientModel::Analytic: s += "#define FACET_IBL_ANALYTIC 1\n"; break;
      case permutations::AmbientModel::TwoMip: s += "#define FACET_IBL_TWO_MIP 1\n"; break;
      case permutations::AmbientModel::Sampled:
        s += "#define FACET_IBL_SAMPLED 1\n#define FACET_IBL_SAMPLES " +
             std::to_string(std::max(in.tier.ambientSamples, 1)) + "\n";
        break;
    }
    // The sampled ground truth applies the same factor (from the same table) as the split sum it
    // measures: it integrates the single-scattering lobe, the factor is part of the model.
    if (in.tier.energyCompensation && (in.tier.ambient == permutations::AmbientModel::SplitSum ||
                                       in.tier.ambient == permutations::AmbientModel::Sampled))
      s += "#define FACET_ENERGY_COMPENSATION 1\n";
    if (in.tier.dominantDirection && in.tier.ambient != permutations::AmbientModel::Sampled)
      s += "#define FACET_IBL_DOMINANT_DIRECTION 1\n";
    s += "#define FACET_SH_BANDS " + std::to_string(in.tier.shBands == 2 ? 2 : in.tier.shBands > 3 ? 5 : 3) + "\n";
    s += "#define FACET_ENVIRONMENT_LEVELS " + std::to_string(kEnvironmentLevels) + "\n";
  }
  return s + "\n";
}

const char* tierPrecision(const permutations::TierConfig& tier) {
  return tier.precision == permutations::PrecisionPolicy::Highp ? "highp" : "mediump";
}

// Varying declarations in order: locations from 0 on the Vulkan flavour, the tier's precision
// unless the type says highp.
struct VaryingDeclarations {
  const AssemblyInput& in;
  Flavour flavour;
  const char* direction;  // "out" or "in"
  std::string text;
  int location = 0;

  void operator()(const std::string& type, const char* name) {
    if (flavour == Flavour::Vulkan) text += "layout(location = " + std::to_string(location++) + ") ";
    std::string qualified = type.rfind("highp ", 0) == 0 ? type : tierPrecision(in.tier) + std::string(" ") + type;
    text += std::string(direction) + " " + qualified + " " + name + ";\n";
  }
};

std::string varyings(const AssemblyInput& in, Flavour flavour, const char* direction) {
  VaryingDeclarations declare{in, flavour, direction};
  if (worldPositionVarying(in))
    declare("highp vec3", "v_worldPosition");
  else
    declare(viewVectorMediump(in) ? "vec3" : "highp vec3", "v_toEye");
  declare("vec3", "v_normal");
  for (const OptionalInput& v : kOptionalInputs)
    if (needs(in, v)) declare(v.varyingType, v.varying);
  if (vertexDiffuse(in)) declare("vec3", "v_diffuseLight");  // diffuse irradiance / π, lit per vertex
  // The sun's n·l / π alone, for a receiver to shadow (templates/forward.vert.glsl).
  if (vertexDiffuse(in) && receivesShadow(in)) declare("float", "v_sunDiffuse");
  // Light slot 0's irradiance / π per unit colour, for a spot-shadow receiver to shadow.
  if (vertexDiffuse(in) && receivesSpotShadow(in)) declare("float", "v_spotDiffuse");
  // The lights' per-vertex diffuse apart from the ambient's, which ambient occlusion scales.
  if (vertexDiffuse(in) && in.material.surface.outputs.count("ambientOcclusion") > 0)
    declare("vec3", "v_directDiffuse");
  // The sun's frame and view depth of the normal-offset position (chunks/shadow_sun.glsl).
  if (receivesShadow(in)) declare("highp vec4", "v_shadowPosition");
  // The spot's view of the normal-offset position, before the divide (chunks/shadow_spot.glsl).
  if (receivesSpotShadow(in)) declare("highp vec4", "v_spotShadowPosition");
  return declare.text;
}

// The vertex inputs the variant reads, from shader_abi.h's attribute table: always highp (read as
// stored), vecN for N components, named a_<name>.
std::string vertexInput(uint32_t location) {
  const abi::VertexAttribute& a = abi::vertexAttribute(location);
  return "layout(location = " + std::to_string(a.location) + ") in highp vec" + std::to_string(a.components) + " a_" +
         std::string(a.name) + ";\n";
}

std::string vertexInputs(const AssemblyInput& in) {
  std::string s = vertexInput(abi::kAttribPosition) + vertexInput(abi::kAttribNormal);
  for (const OptionalInput& v : kOptionalInputs)
    if (needs(in, v)) s += vertexInput(v.location);
  for (const abi::VertexAttribute& a : abi::kInstanceAttributes) s += vertexInput(a.location);
  return s;
}

// MaterialInputs, its defaults and the material's surface program.
std::string materialSection(const AssemblyInput& in) {
  std::string s =
      "// Surface outputs; an output the material does not write keeps its default.\nstruct MaterialInputs {\n";
  // An output that exists only with another is a member only where the material writes that one
  // (ir::OutputInfo::presentWith): other materials' shaders stay as they were.
  // The cloth model's outputs likewise exist only in cloth materials' variants, the sheen's in
  // those and where a lit material writes it.
  auto member = [&](const ir::OutputInfo& o) {
    return (!o.presentWith || (in.material.surface.outputs.count(o.presentWith) > 0 &&
                               !(o.model == ir::OutputModel::Standard && shadesCloth(in)))) &&
           (o.model != ir::OutputModel::Cloth || shadesCloth(in)) &&
           (o.model != ir::OutputModel::Sheen || shadesCloth(in) || writesSheenLayer(in));
  };
  for (const ir::OutputInfo& o : ir::outputs())
    if (member(o)) s += "    " + std::string(ir::glslName(o.type)) + " " + o.name + ";\n";
  s += "};\n\nMaterialInputs material_defaults() {\n    MaterialInputs m;\n";
  for (const ir::OutputInfo& o : ir::outputs())
    if (member(o)) s += "    m." + std::string(o.name) + " = " + ir::glslConstant(o.type, o.defaultValue) + ";\n";
  s += "    return m;\n}\n\n";
  s += "// The interpolated, normalized world-space normal (vertex.normal in the material), and the\n"
       "// unit vector from the surface to the eye (vertex.viewDirection).\nvec3 shading_normal;\nvec3 "
       "shading_view;\n\n";
  s += "// Surface program of material '" + in.material.name + "'.\n";
  s += "void evaluate_surface(inout MaterialInputs material) {\n" + in.surface.body + "}\n";
  return s;
}

// The `lut` specular table (specular_lut_lobe.glsl), shader_abi.h kSpecularLutSampler. Its texels
// ship in the package.
// Declared wherever the lobe is compiled; a variant without the light never calls the lobe, and
// the unused sampler is dropped (samplesSpecularLut says which variants read it).
std::string specularLutSampler(const AssemblyInput& in, Flavour flavour, const char* precision) {
  if (in.tier.specular != permutations::SpecularModel::Lut || in.material.shading != "lit") return "";
  return frameSampler(flavour, abi::kSpecularLutSampler, precision);
}

// The frame textures of image-based lighting (shader_abi.h): the prefiltered environment in every
// lit variant, the DFG table in split-sum ones (and the sampled ground truth's, for the energy
// compensation), the irradiance cube in `cube` diffuse ones.
// Fragment stage only: the vertex stage evaluates SH from the frame block, never a texture.
std::string iblSamplers(const AssemblyInput& in, Flavour flavour, const char* precision) {
  if (in.material.shading != "lit") return "";
  std::string s = frameSampler(flavour, abi::kEnvironmentSampler, precision);
  if (samplesDfgLut(in)) s += frameSampler(flavour, abi::kDfgLutSampler, precision);
  if (cubeDiffuse(in)) s += frameSampler(flavour, abi::kIrradianceSampler, precision);
  return s;
}

// The sun's shadow: its block and its compare sampler (fragment stage only), highp: the sampler's
// coordinate is an atlas position and a depth (chunks/shadow_sun.glsl).
// The block is in both stages (the vertex stage moves the position into the sun's frame), the same
// text in each as GLSL ES requires.
std::string shadowBlock(const AssemblyInput& in, Flavour flavour) {
  return readsShadowAtlas(in) ? fixedBlock(flavour, abi::kShadowBlock) : "";
}

std::string shadowAtlasSampler(const AssemblyInput& in, Flavour flavour) {
  if (!readsShadowAtlas(in)) return "";
  const abi::SamplerDesc& atlas = abi::kShadowAtlasSampler;
  return samplerLayout(flavour, atlas.set, atlas.binding) + "uniform highp sampler2DShadow " + std::string(atlas.name) +
         ";\n";
}

// The chunk that defines specular_lobe() for a tier's specular model.
std::string specularChunk(permutations::SpecularModel model) {
  switch (model) {
    case permutations::SpecularModel::GgxSmith: return "specular_ggx_smith.glsl";
    case permutations::SpecularModel::GgxFastV: return "specular_ggx_fastv.glsl";
    case permutations::SpecularModel::FusedHammon: return "specular_fused_hammon.glsl";
    case permutations::SpecularModel::Zioma: return "specular_zioma_lobe.glsl";
    case permutations::SpecularModel::Lut: return "specular_lut_lobe.glsl";
  }
  return "";
}

// Replaces each `#include "name"` line with the named chunk, recursively (a chunk includes what
// it needs), each chunk once: the first include places it.
bool expandIncludes(const std::string& text, const AssemblyInput& in, std::set<std::string>& included, int depth,
                    std::string* out, std::string* error) {
  if (depth > 8) {
    *error = "internal error: chunk includes nest deeper than 8";
    return false;
  }
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    const std::string directive = "#include \"";
    if (line.rfind(directive, 0) != 0) {
      *out += line + "\n";
      continue;
    }
    std::string name = line.substr(directive.size(), line.size() - directive.size() - 1);
    if (name == "facet:specular") name = specularChunk(in.tier.specular);
    if (!included.insert(name).second) continue;
    if (name == "facet:material") {
      *out += materialSection(in) + "\n";
      continue;
    }
    auto it = glslLibrary().find(name);
    if (it == glslLibrary().end()) {
      *error = "internal error: template includes unknown chunk '" + name + "'";
      return false;
    }
    *out += "// ---- chunks/" + name + " ----\n";
    if (!expandIncludes(it->second, in, included, depth + 1, out, error)) return false;
    *out += "\n";
  }
  return true;
}

bool expandIncludes(const std::string& text, const AssemblyInput& in, std::string* out, std::set<std::string>* used,
                    std::string* error) {
  std::set<std::string> included;
  if (!expandIncludes(text, in, included, 0, out, error)) return false;
  for (const std::string& name : included)
    if (name.rfind("facet:", 0) != 0) used->insert(name);
  return true;
}

bool templateText(const char* name, const std::string** text, std::string* error) {
  auto it = glslLibrary().find(name);
  if (it == glslLibrary().end()) {
    *error = std::string("internal error: missing template '") + name + "'";
    return false;
  }
  *text = &it->second;
  return true;
}

// Both stages' text into *out, with the line where the surface program's body starts (so that a
// backend's error there maps back to the material).
void finishStages(std::string vertex, std::string fragment, StageSources* out) {
  const std::string bodyStart = "void evaluate_surface(inout MaterialInputs material) {\n";
  if (size_t at = fragment.find(bodyStart); at != std::string::npos)
    out->fragmentSurfaceLine = uint32_t(std::count(fragment.begin(), fragment.begin() + long(at), '\n')) + 2;
  out->vertex = std::move(vertex);
  out->fragment = std::move(fragment);
}

// The shadow pass's depth-only program (VariantKey::depthOnly; templates/depth.*.glsl). Its
// inputs: the position and instance rows, and for a masked material what its alpha reads, given
// here by in.surface (the surface program reduced to `alpha`, compiler/build.cpp).
const OptionalInput* depthInput(const AssemblyInput& in, const OptionalInput& v) {
  if (in.material.blending != "masked" || v.location == abi::kAttribTangent) return nullptr;
  return in.surface.attributes.count(std::string(v.name())) > 0 ? &v : nullptr;
}

bool depthWorldPosition(const AssemblyInput& in) {
  return in.material.blending == "masked" && in.surface.attributes.count("worldPosition") > 0;
}

std::string depthPrologue(const AssemblyInput& in, Flavour flavour, const char* stage, const char* floatPrecision) {
  std::string s = flavour == Flavour::GlslEs300 ? "#version 300 es\n" : "#version 310 es\n";
  s += "// Material '" + in.material.name + "', depth-only program of tier " + permutations::toString(in.key.tier) +
       (in.key.vertexSlopeBias && std::string_view(stage) == "vertex" ? " with the vertex-stage slope bias" : "") +
       " (shadow pass), " + stage + " stage, " +
       (flavour == Flavour::GlslEs300 ? "GLSL ES 3.00 (OpenGL ES)" : "Vulkan flavour (input to SPIR-V and MSL)") +
       ".\n// Generated by " + in.compilerVersion + ". Do not edit: change the material and recompile.\n";
  s += std::string("precision ") + floatPrecision + " float;\nprecision highp int;\n";
  for (const OptionalInput& v : kOptionalInputs)
    if (depthInput(in, v)) s += "#define FACET_VARYING_" + upper(std::string(v.name())) + " 1\n";
  if (depthWorldPosition(in)) s += "#define FACET_VARYING_WORLD_POSITION 1\n";
  if (in.material.blending == "masked") {
    s += "#define FACET_BLENDING_MASKED 1\n";
    s += "#define FACET_ALPHA_CUTOFF " + ir::glslConstant(ir::Type::Float, {in.material.alphaCutoff}) + "\n";
  }
  if (in.tier.precision == permutations::PrecisionPolicy::Highp) s += "#define FACET_PRECISION_HIGHP 1\n";
  if (in.key.vertexSlopeBias && std::string_view(stage) == "vertex") s += "#define FACET_VERTEX_SLOPE_BIAS 1\n";
  return s + "\n";
}

std::string depthVaryings(const AssemblyInput& in, Flavour flavour, const char* direction) {
  VaryingDeclarations declare{in, flavour, direction};
  if (depthWorldPosition(in)) declare("highp vec3", "v_worldPosition");
  for (const OptionalInput& v : kOptionalInputs)
    if (depthInput(in, v)) declare(v.varyingType, v.varying);
  return declare.text;
}

bool assembleDepth(const AssemblyInput& in, Flavour flavour, StageSources* out, std::string* error) {
  // What the shadow pass cannot give a masked material's alpha: a normal (it sends none) and the
  // direction to an eye (the pass looks along the sun's rays, not from the camera).
  for (const char* attribute : {"normal", "viewDirection"}) {
    if (in.material.blending == "masked" && in.surface.attributes.count(attribute) > 0) {
      *error = "masked material '" + in.material.name + "': its alpha reads vertex." + attribute +
               ", which the shadow pass's depth-only program does not have (it interpolates vertex.uv0, "
               "vertex.uv1, vertex.color and vertex.worldPosition); make alpha independent of it, or build "
               "without shadows";
      return false;
    }
  }
  const std::string* vertexTemplate = nullptr;
  const std::string* fragmentTemplate = nullptr;
  if (!templateText("depth.vert.glsl", &vertexTemplate, error) ||
      !templateText("depth.frag.glsl", &fragmentTemplate, error))
    return false;
  std::string vs = depthPrologue(in, flavour, "vertex", "highp") + vertexInput(abi::kAttribPosition);
  if (in.key.vertexSlopeBias) vs += vertexInput(abi::kAttribNormal);
  for (const OptionalInput& v : kOptionalInputs)
    if (depthInput(in, v)) vs += vertexInput(v.location);
  for (const abi::VertexAttribute& a : abi::kInstanceAttributes) vs += vertexInput(a.location);
  vs += "\n" + depthVaryings(in, flavour, "out") + "\n" + frameBlock(flavour, in.tier) +
        fixedBlock(flavour, abi::kObjectBlock) + "\n";
  out->libraryFiles = {"depth.vert.glsl", "depth.frag.glsl"};
  if (!expandIncludes(*vertexTemplate, in, &vs, &out->libraryFiles, error)) return false;

  const char* fragmentPrecision = tierPrecision(in.tier);
  std::string fs = depthPrologue(in, flavour, "fragment", fragmentPrecision);
  if (in.material.blending == "masked") {
    // The material's block as the forward variants declare it (the runtime binds the same one), no
    // preshaded members: alpha is never preshaded.
    fs += depthVaryings(in, flavour, "in") + "\n" +
          materialBlock(flavour, in.material, in.params, nullptr, fragmentPrecision) +
          materialSamplers(flavour, in.params, fragmentPrecision) + "\n";
  }
  if (!expandIncludes(*fragmentTemplate, in, &fs, &out->libraryFiles, error)) return false;
  finishStages(std::move(vs), std::move(fs), out);
  return true;
}

}  // namespace

bool samplesEnvironment(const AssemblyInput& in) { return in.material.shading == "lit" && !in.key.depthOnly; }

bool samplesIrradianceCube(const permutations::TierConfig& tier, const std::string& shading) {
  return tier.diffuse == permutations::DiffuseModel::Cube && shading == "lit" &&
         tier.ambient != permutations::AmbientModel::Sampled;
}

bool samplesShadowAtlas(const AssemblyInput& in) { return readsShadowAtlas(in); }

bool samplesDfgLut(const AssemblyInput& in) {
  if (in.key.depthOnly) return false;
  // A sheen (the cloth model's, or a layer over the standard one) reads its terms from the table
  // whatever the ambient model.
  if ((shadesCloth(in) || writesSheenLayer(in)) && in.tier.sheen != permutations::SheenModel::None) return true;
  return in.material.shading == "lit" && (in.tier.ambient == permutations::AmbientModel::SplitSum ||
                                          in.tier.ambient == permutations::AmbientModel::Sampled);
}

// Every light of a lut tier reads the table (specular_lut_lobe.glsl): the sun and each point or
// spot light; unless the anisotropic lobe replaces the tier's (anisotropy_ggx_smith.glsl).
bool samplesSpecularLut(const AssemblyInput& in) {
  return in.tier.specular == permutations::SpecularModel::Lut && in.material.shading == "lit" &&
         !shadesAnisotropicLobe(in) && !shadesCloth(in) && (in.key.directionalLight || in.key.pointLights > 0);
}

bool assemble(const AssemblyInput& in, Flavour flavour, StageSources* out, std::string* error) {
  if (in.key.depthOnly) return assembleDepth(in, flavour, out, error);
  const std::string* vertexTemplate = nullptr;
  const std::string* fragmentTemplate = nullptr;
  const char* fragmentName = in.material.shading == "unlit" ? "forward_unlit.frag.glsl" : "forward_lit.frag.glsl";
  if (!templateText("forward.vert.glsl", &vertexTemplate, error) ||
      !templateText(fragmentName, &fragmentTemplate, error))
    return false;

  std::string vs = prologue(in, flavour, "vertex", "highp");
  vs += vertexInputs(in) + "\n" + varyings(in, flavour, "out") + "\n" + frameBlock(flavour, in.tier) +
        fixedBlock(flavour, abi::kObjectBlock) + shadowBlock(in, flavour) + "\n";
  out->libraryFiles = {"forward.vert.glsl", fragmentName};
  if (!expandIncludes(*vertexTemplate, in, &vs, &out->libraryFiles, error)) return false;

  // The fragment stage's default float precision is the tier's policy: mediump (fp16 on mobile)
  // with the clamps of precision.glsl, or highp for the reference tier.
  const char* fragmentPrecision = tierPrecision(in.tier);
  std::string fs = prologue(in, flavour, "fragment", fragmentPrecision);
  fs += varyings(in, flavour, "in") + "layout(location = " + std::to_string(abi::kForwardColorLocation) + ") out " +
        fragmentPrecision + " vec4 fragColor;\n\n";
  fs += frameBlock(flavour, in.tier) + materialBlock(flavour, in.material, in.params, in.preshade, fragmentPrecision) +
        materialSamplers(flavour, in.params, fragmentPrecision) + specularLutSampler(in, flavour, fragmentPrecision) +
        iblSamplers(in, flavour, fragmentPrecision) + shadowBlock(in, flavour) + shadowAtlasSampler(in, flavour) + "\n";
  if (!expandIncludes(*fragmentTemplate, in, &fs, &out->libraryFiles, error)) return false;
  finishStages(std::move(vs), std::move(fs), out);
  return true;
}

std::string uniformBlockDeclaration(Flavour flavour, const abi::BlockDesc& block) { return fixedBlock(flavour, block); }

namespace {

// Chunks on their own, includes resolved: the lobe chunks read nothing of the material, so an
// empty one stands in for it.
bool standaloneSource(const std::string& includes, permutations::SpecularModel model, std::string* out,
                      std::string* error) {
  static const ir::Material noMaterial;
  static const ir::SurfaceGlsl noSurface;
  static const ParamLayout noParams;
  AssemblyInput in{noMaterial, noSurface, noParams, {}, {}, ""};
  in.tier.specular = model;
  std::set<std::string> used;
  return expandIncludes(includes, in, out, &used, error);
}

}  // namespace

bool specularLobeSource(permutations::SpecularModel model, std::string* out, std::string* error) {
  return standaloneSource("#include \"precision.glsl\"\n#include \"math.glsl\"\n#include \"facet:specular\"\n", model,
                          out, error);
}

bool chunkSource(const std::vector<std::string>& names, std::string* out, std::string* error) {
  std::string includes;
  for (const std::string& name : names) includes += "#include \"" + name + "\"\n";
  return standaloneSource(includes, permutations::SpecularModel::GgxSmith, out, error);
}

}  // namespace facet::compiler
