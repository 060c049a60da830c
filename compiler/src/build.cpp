#include "facet/compiler/build.h"

#include <cstring>

#include "facet/compiler/assemble.h"
#include "facet/compiler/backend_errors.h"
#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/msl_backend.h"
#include "facet/compiler/param_layout.h"
#include "facet/compiler/specular_lut.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/ir/emit_glsl.h"
#include "facet/ir/passes.h"
#include "lower_relaxed_to_quantized.h"

namespace facet::compiler {
namespace {

std::vector<uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

std::vector<uint8_t> bytesOf(const std::vector<uint32_t>& words) {
  std::vector<uint8_t> bytes(words.size() * 4);
  std::memcpy(bytes.data(), words.data(), bytes.size());  // SPIR-V words are stored little-endian
  return bytes;
}

package::ParamType packageType(const ir::Param& p) {
  if (p.isColor) return package::ParamType::Color;
  switch (p.type) {
    case ir::Type::Texture2D:
      if (p.textureSpace == ir::TextureSpace::Srgb) return package::ParamType::TextureSrgb;
      if (p.textureSpace == ir::TextureSpace::Normal) return package::ParamType::TextureNormal;
      return package::ParamType::TextureLinear;
    case ir::Type::Float: return package::ParamType::Float;
    case ir::Type::Vec2: return package::ParamType::Vec2;
    case ir::Type::Vec3: return package::ParamType::Vec3;
    case ir::Type::Vec4: return package::ParamType::Vec4;
    case ir::Type::Int: return package::ParamType::Int;
    case ir::Type::Bool: return package::ParamType::Bool;
  }
  return package::ParamType::Float;
}

package::MaterialInfo materialInfo(const ir::Material& m, const ParamLayout& layout) {
  package::MaterialInfo info;
  info.name = m.name;
  info.shading = m.shading;
  info.blending = m.blending;
  info.doubleSided = m.doubleSided;
  info.paramBlockSize = layout.blockSize;
  for (size_t i = 0; i < m.params.size(); ++i) {
    const ir::Param& p = m.params[i];
    package::Param out;
    out.name = p.name;
    out.type = packageType(p);
    out.defaultValue = p.defaultValue;
    out.rangeMin = p.rangeMin;
    out.rangeMax = p.rangeMax;
    out.offset = layout.slots[i].offset;
    out.size = layout.slots[i].size;
    if (package::isTexture(out.type))
      out.offset = layout.slots[i].textureSlot < 0 ? package::kNoTextureSlot : uint32_t(layout.slots[i].textureSlot);
    info.params.push_back(std::move(out));
  }
  return info;
}

// One stage's SPIR-V: validate what glslang produced, optimize, validate again.
bool finishSpirv(std::vector<uint32_t>* words, const char* stage, std::string* error) {
  std::string log;
  if (!validateSpirv(*words, &log)) {
    *error = std::string("spirv-val rejected the ") + stage + " stage from glslang:\n" + log;
    return false;
  }
  if (!optimizeSpirv(words, &log)) {
    *error = std::string("spirv-opt failed on the ") + stage + " stage:\n" + log;
    return false;
  }
  if (!validateSpirv(*words, &log)) {
    *error = std::string("spirv-val rejected the optimized ") + stage + " stage:\n" + log;
    return false;
  }
  return true;
}

// BuildOptions::fp16Emulation: glslang's unoptimized stages with every relaxed float result
// rounded to binary16, then validated and optimized as usual.
bool emulateFp16(SpirvStages* stages, std::string* error) {
  for (auto [words, stage] : {std::pair{&stages->vertex, "fp16-emulated vertex"}, {&stages->fragment, "fp16-emulated fragment"}}) {
    QuantizeCounts counts;
    if (!lowerRelaxedToQuantized(words, &counts, error) || !finishSpirv(words, stage, error)) return false;
  }
  return true;
}

// A glslang failure on generated code: blamed on the material line that produced it when the
// error lies in the surface program, else reported as the compiler's own defect.
void reportGlslangFailure(const std::string& log, const StageSources& sources, const ir::SurfaceGlsl& surface,
                          const std::string& what, BuildError* failure) {
  if (auto mapped = mapGlslangErrors(log, sources.fragmentSurfaceLine, surface.lineLocs)) {
    failure->message = "the shader compiler rejected this expression: " + mapped->message + " (" + what + ")";
    failure->loc = mapped->loc;
    return;
  }
  failure->message = "internal error: generated " + what + " does not compile:\n" + log;
}

}  // namespace

const std::string& compilerVersion() {
  static const std::string version = std::string("facet-matc ") + FACET_VERSION;
  return version;
}

permutations::TierConfig tierConfig(const ir::Material& material, permutations::Tier tierName, const BuildOptions& options) {
  // The tier's preset, with the material's overrides for that tier (checked by ir::check).
  permutations::TierConfig tier = permutations::preset(tierName);
  for (const ir::TierOverride& o : material.tierOverrides)
    if (o.tier == permutations::toString(tierName)) permutations::applyOverride(&tier, o.axis, o.option);
  if (options.adjustTier) options.adjustTier(tierName, &tier);
  return tier;
}

std::optional<BuildResult> buildMaterial(const ir::Material& checked, const BuildOptions& options, BuildError* failure) {
  std::string* error = &failure->message;
  BuildResult result;
  ir::Material material = checked;
  ir::optimize(material);
  ParamLayout layout = layoutParams(material.params);
  ir::SurfaceGlsl surface = ir::emitSurface(material);
  result.package.compilerVersion = compilerVersion();
  result.package.material = materialInfo(material, layout);

  permutations::MaterialNeeds needs;
  needs.lit = material.shading == "lit";
  const permutations::SceneNeeds* scene = options.scene ? &*options.scene : nullptr;
  std::vector<uint32_t> lutVariants;  // indices of the variants that sample the specular table
  for (const permutations::VariantKey& key : permutations::enumerate(needs, options.tiers, scene, options.pointLightCounts)) {
    const std::string keyText = key.toString();
    const permutations::TierConfig tier = tierConfig(material, key.tier, options);
    AssemblyInput input{material, surface, layout, key, tier, compilerVersion()};
    StageSources es, vk;
    if (!assemble(input, Flavour::GlslEs300, &es, error) || !assemble(input, Flavour::Vulkan, &vk, error)) return std::nullopt;
    const std::string stem = material.name + "." + keyText;
    result.sources.push_back({stem + ".vert.es300.glsl", es.vertex});
    result.sources.push_back({stem + ".frag.es300.glsl", es.fragment});
    result.sources.push_back({stem + ".vert.vulkan.glsl", vk.vertex});
    result.sources.push_back({stem + ".frag.vulkan.glsl", vk.fragment});

    std::string log;
    if (!checkGlslEs300(es, &log)) {
      reportGlslangFailure(log, es, surface, "GLSL ES 3.00 for variant " + keyText, failure);
      return std::nullopt;
    }
    SpirvStages spirv;
    if (!compileToSpirv(vk, &spirv, &log)) {
      reportGlslangFailure(log, vk, surface, "SPIR-V for variant " + keyText, failure);
      return std::nullopt;
    }
    // fp16 emulation replaces only the Vulkan target; it must see the stages before spirv-opt.
    std::optional<SpirvStages> emulated;
    if (options.fp16Emulation && tier.precision == permutations::PrecisionPolicy::Mediump) {
      emulated = spirv;
      if (!emulateFp16(&*emulated, error)) return std::nullopt;
    }
    if (!finishSpirv(&spirv.vertex, "vertex", error) || !finishSpirv(&spirv.fragment, "fragment", error)) return std::nullopt;
    const SpirvStages& vulkan = emulated ? *emulated : spirv;
    // Metal: mediump becomes `half` (16-bit) through spirv-opt, as on GLES drivers.
    std::vector<uint32_t> metalVertex = spirv.vertex, metalFragment = spirv.fragment;
    if (!convertRelaxedToHalf(&metalVertex, &log) || !convertRelaxedToHalf(&metalFragment, &log)) {
      *error = "internal error: spirv-opt --convert-relaxed-to-half failed for variant " + keyText + ":\n" + log;
      return std::nullopt;
    }
    std::string mslVertex, mslFragment;
    if (!spirvToMsl(metalVertex, &mslVertex, error) || !spirvToMsl(metalFragment, &mslFragment, error)) return std::nullopt;
    result.sources.push_back({stem + ".vert.spvasm", disassembleSpirv(vulkan.vertex)});
    result.sources.push_back({stem + ".frag.spvasm", disassembleSpirv(vulkan.fragment)});
    result.sources.push_back({stem + ".vert.metal", mslVertex});
    result.sources.push_back({stem + ".frag.metal", mslFragment});

    using package::Stage;
    using package::Target;
    package::Variant variant;
    variant.key = keyText;
    variant.shaders = {
        {Stage::Vertex, Target::GlslEs300, bytesOf(es.vertex)},
        {Stage::Fragment, Target::GlslEs300, bytesOf(es.fragment)},
        {Stage::Vertex, Target::Spirv, bytesOf(vulkan.vertex)},
        {Stage::Fragment, Target::Spirv, bytesOf(vulkan.fragment)},
        {Stage::Vertex, Target::Msl, bytesOf(mslVertex)},
        {Stage::Fragment, Target::Msl, bytesOf(mslFragment)},
    };
    if (samplesSpecularLut(input)) lutVariants.push_back(uint32_t(result.package.variants.size()));
    result.package.variants.push_back(std::move(variant));
  }
  // The `lut` tier's table travels with the package (section TEXS), so the runtime needs no
  // compiler code and the texels always match the chunk that decodes them.
  if (!lutVariants.empty()) {
    SpecularLut lut = generateSpecularLut();
    result.package.textures.push_back({kSpecularLutSamplerName, lut.width, lut.height, package::TexelFormat::R8Unorm,
                                       std::move(lut.texels), std::move(lutVariants)});
  }
  return result;
}

}  // namespace facet::compiler
