#include "facet/package/checks.h"

#include <algorithm>
#include <cstring>

#include "facet/abi/shader_abi.h"
#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"
#include "spirv_reflection.h"
#include "untrusted_spirv.h"

namespace facet::package {
namespace {

// Frame-texture slots: the shaders declare them at these bindings whatever material they belong to.
constexpr GeneratedTextureSlot kGeneratedSlots[] = {
    {abi::kSpecularLutName, abi::kSpecularLutBinding, abi::kSpecularLutWidth, abi::kSpecularLutHeight}};

// A parameter's value type in the block: float and vectors, int, bool (4 bytes a component).
ValueType valueTypeOf(const Param& p) {
  const ScalarKind kind = p.type == ParamType::Int    ? ScalarKind::Int
                          : p.type == ParamType::Bool ? ScalarKind::Bool
                                                      : ScalarKind::Float;
  return {kind, uint32_t(p.size / 4)};
}

}  // namespace

const GeneratedTextureSlot* generatedTextureSlot(const std::string& name) {
  for (const GeneratedTextureSlot& s : kGeneratedSlots)
    if (name == s.name) return &s;
  return nullptr;
}

std::string unknownTextureError(const std::string& material, const std::string& variantKey,
                                const std::string& texture) {
  return "material '" + material + "' variant '" + variantKey + "' samples texture '" + texture +
         "', which this runtime does not know; update the runtime or recompile the material";
}

std::string loadError(const PackageReader& reader) {
  // The tables' meaning now; each shader's code when checkVariant first decodes it.
  if (std::string why = reader.semanticError(); !why.empty()) return why;
  // Before format 1.4 a lit material's shaders read the environment as a 2D map: octahedral in
  // 1.2 and 1.3 (both came after the octahedral map), equirect or octahedral in 1.0 and 1.1. This
  // runtime no longer builds either (it binds a cube map there): the package cannot be drawn.
  const uint16_t minor = reader.formatMinor();
  if (reader.material().shading == "lit" && minor < kFirstMinorWithCubeEnvironment) {
    return "package format 1." + std::to_string(minor) + " samples the environment as " +
           (minor >= 2 ? "an octahedral map" : "a 2D map (equirect or octahedral)") +
           ", which this runtime no longer provides (a cube map since format 1." +
           std::to_string(kFirstMinorWithCubeEnvironment) +
           "); rebuild it with this release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg";
  }
  // Before format 1.5 every shader read one interleaved fp32 vertex stream with no decode; this
  // runtime binds two packed streams (runtime/vertex_packing.h): such a package would draw its
  // meshes squashed into the unit cube.
  if (minor < kFirstMinorWithPackedVertices && !reader.variants().empty()) {
    return "package format 1." + std::to_string(minor) +
           " reads one interleaved fp32 vertex stream, which this runtime no longer provides (two packed "
           "streams since format 1." +
           std::to_string(kFirstMinorWithPackedVertices) +
           "); rebuild it with this release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg";
  }
  // Before format 1.6 the vertex shaders read the model and normal matrices from ObjectUniforms;
  // this runtime's block holds only the mesh's decoding and streams the transform per instance.
  if (minor < kFirstMinorWithInstanceTransforms && !reader.variants().empty()) {
    return "package format 1." + std::to_string(minor) +
           " reads its transform from ObjectUniforms, which this runtime no longer provides (per-instance "
           "transforms since format 1." +
           std::to_string(kFirstMinorWithInstanceTransforms) +
           "); rebuild it with this release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg";
  }
  // A table of another shape, even one of the same byte count, would be sampled at the wrong
  // texels: the shaders address it with the ABI's size.
  for (const TextureInfo& t : reader.textures()) {
    const GeneratedTextureSlot* slot = generatedTextureSlot(t.name);
    if (slot && (t.width != slot->width || t.height != slot->height)) {
      return "texture '" + t.name + "' is " + std::to_string(t.width) + "x" + std::to_string(t.height) +
             "; the shaders address it as " + std::to_string(slot->width) + "x" + std::to_string(slot->height);
    }
  }
  return "";
}

std::optional<ProgramInterface> variantInterface(const PackageReader& reader, size_t variant, std::string* error) {
  const MaterialInfo& m = reader.material();
  const std::string& key = reader.variants()[variant].key;
  ProgramInterface out;
  out.material = m.name;
  out.variant = key;
  out.parameterBytes = m.paramBlockSize;
  const PreshaderProgram* program = reader.preshaderProgram(key);
  out.materialBlockBytes = program ? reader.preshader().blockSize : m.paramBlockSize;
  out.preshadedWords.assign(out.materialBlockBytes / 4, false);
  if (program)
    for (const PreshaderOp& op : program->ops)
      if (op.code == PreshaderOpcode::Store)
        for (uint32_t i = 0; i < op.count && op.offset / 4 + i < out.preshadedWords.size(); ++i)
          out.preshadedWords[op.offset / 4 + i] = true;
  for (const Param& p : m.params) {
    if (isTexture(p.type)) {
      if (p.offset != kNoTextureSlot)
        out.samplers.push_back({abi::kMaterialSamplerPrefix + p.name, abi::materialTextureBinding(p.offset), false});
    } else if (p.size != 0) {
      out.parameters.push_back({p.name, p.offset, valueTypeOf(p)});
    }
  }
  // The frame's textures a lit variant's draws bind (runtime/scene_frame.h): the environment, the
  // irradiance cube, and the DFG table in the tiers whose ambient model reads it (elsewhere its binding holds a dummy).
  // The key parses: semanticError checked it.
  const std::optional<permutations::VariantKey> parsed = permutations::VariantKey::parse(key);
  const bool splitSum = parsed && permutations::preset(parsed->tier).ambient == permutations::AmbientModel::SplitSum;
  const auto frame = [&](const abi::SamplerDesc& d) {
    out.samplers.push_back({std::string(d.name), d.binding, d.cube, d.shadow});
  };
  // The shadow pass binds no frame texture: a depth-only program reads the position, and a masked
  // material's alpha its own textures.
  out.depthOnly = parsed && parsed->depthOnly;
  const bool lit = m.shading == "lit" && !out.depthOnly;
  // A `cube` diffuse tier reads the irradiance cube; the package does not record which tiers do.
  if (lit) {
    frame(abi::kEnvironmentSampler);
    frame(abi::kIrradianceSampler);
  }
  // Receivers bind the shadow block and atlas (chunks/shadow_sun.glsl, chunks/shadow_spot.glsl).
  out.shadowReceiver = parsed && parsed->receivesShadow() && m.shading == "lit";
  if (out.shadowReceiver) frame(abi::kShadowAtlasSampler);
  if (lit && splitSum) frame(abi::kDfgLutSampler);
  for (const TextureInfo& t : reader.textures()) {
    if (std::find(t.variants.begin(), t.variants.end(), variant) == t.variants.end()) continue;
    const GeneratedTextureSlot* slot = generatedTextureSlot(t.name);
    if (!slot) {
      *error = unknownTextureError(m.name, key, t.name);
      return std::nullopt;
    }
    out.samplers.push_back({t.name, slot->binding, false});
    out.packageTextures.push_back(t.name);
  }
  return out;
}

std::optional<CheckedVariant> checkVariant(const PackageReader& reader, size_t variant, std::string* error) {
  const std::string& material = reader.material().name;
  const std::string& key = reader.variants()[variant].key;
  CheckedVariant p;
  std::vector<ReflectedStage> reflected;
  for (const ShaderInfo& s : reader.variants()[variant].shaders) {
    // Metal is not a backend of this runtime: its code stays compressed.
    if (s.target == Target::Msl) continue;
    const std::string what = "material '" + material + "' variant " + key + ": the " + toString(s.stage) + " shader";
    std::optional<std::span<const uint8_t>> code = reader.blob(s.blob, error);
    if (!code) {
      *error = what + ": " + *error;
      return std::nullopt;
    }
    if (std::string why = shaderCodeError(s.target, *code); !why.empty()) {
      *error = "material '" + material + "': the " + toString(s.stage) + " " + toString(s.target) +
               " shader of variant '" + key + "' " + why;
      return std::nullopt;
    }
    bool vertex = s.stage == Stage::Vertex;
    if (s.target == Target::GlslEs300) {
      (vertex ? p.vertexGlslEs : p.fragmentGlslEs).assign(code->begin(), code->end());
    } else if (s.target == Target::Spirv) {
      std::vector<uint32_t>& words = vertex ? p.vertexSpirv : p.fragmentSpirv;
      words.resize(code->size() / 4);
      if (!words.empty()) std::memcpy(words.data(), code->data(), words.size() * 4);
      std::string why;
      if (!validateUntrustedSpirv(words, &why)) {
        *error = what + " is " + why;
        return std::nullopt;
      }
      // Valid on its own is not enough: its stage and interface must be the package's.
      if (!reflectSpirv(words, s.stage, &reflected.emplace_back(), &why)) {
        *error = what + " (SPIR-V) " + why;
        return std::nullopt;
      }
    }
  }
  std::optional<ProgramInterface> declared = variantInterface(reader, variant, error);
  if (!declared) return std::nullopt;
  if (std::string why = interfaceError(*declared, reflected, true); !why.empty()) {
    *error = why;
    return std::nullopt;
  }
  p.interface = std::move(*declared);
  return p;
}

bool checkEveryVariant(const PackageReader& reader, std::string* error) {
  for (size_t i = 0; i < reader.variants().size(); ++i)
    if (!checkVariant(reader, i, error)) return false;
  return true;
}

}  // namespace facet::package
