#include "facet/package/program_interface.h"

#include <algorithm>

#include "facet/abi/shader_abi.h"

namespace facet::package {
namespace {

std::string bytes(uint32_t from, uint64_t to) { return "bytes " + std::to_string(from) + ".." + std::to_string(to); }

bool isParameterType(const ValueType& t) {
  return t.kind != ScalarKind::Other && t.columns == 1 && t.arraySize == 0 && t.components >= 1 && t.components <= 4;
}

// A bool parameter is a uint in SPIR-V (std140 has no bool: glslang stores it as a 32-bit uint)
// and a bool in GL's reflection.
bool holds(const ValueType& parameter, const ValueType& member) {
  if (parameter.kind == ScalarKind::Bool)
    return (member.kind == ScalarKind::Bool || member.kind == ScalarKind::Uint) &&
           member.components == parameter.components && member.columns == 1 && member.arraySize == 0;
  return member == parameter;
}

class StageCheck {
 public:
  StageCheck(const ProgramInterface& declared, const ReflectedStage& stage) : declared_(declared), stage_(stage) {}

  std::string run() {
    for (const ReflectedBlock& b : stage_.blocks)
      if (std::string e = block(b); !e.empty()) return e;
    for (const ReflectedSampler& s : stage_.samplers)
      if (std::string e = sampler(s); !e.empty()) return e;
    if (!stage_.unsupported.empty())
      return "declares " + stage_.unsupported.front() + ", which the runtime does not bind";
    if (stage_.stage == package::Stage::Vertex)
      for (const ReflectedVariable& v : stage_.inputs)
        if (std::string e = vertexInput(v); !e.empty()) return e;
    if (stage_.stage == package::Stage::Fragment)
      for (const ReflectedVariable& v : stage_.outputs)
        if (std::string e = fragmentOutput(v); !e.empty()) return e;
    return "";
  }

 private:
  std::string blockName(const ReflectedBlock& b) const {
    if (stage_.bindsByName || !b.name.empty()) return "uniform block '" + b.name + "'";
    return "the uniform block at set " + std::to_string(b.set) + " binding " + std::to_string(b.binding);
  }

  std::string block(const ReflectedBlock& b) const {
    const abi::BlockDesc* desc = nullptr;
    for (const abi::BlockDesc& d : abi::kBlocks)
      if (stage_.bindsByName ? b.name == d.name : (b.set == d.set && b.binding == d.binding)) desc = &d;
    if (!desc) {
      if (stage_.bindsByName) return "declares " + blockName(b) + ", which the runtime does not bind";
      return "declares " + blockName(b) + " at set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) +
             ", where the runtime binds no block";
    }
    const std::string name(desc->name);
    if (desc->name == abi::kShadowBlock.name && !declared_.shadowReceiver)
      return "reads " + name + ", which only a shadow receiver's (.sh, .sp1) draws bind";
    if (b.arraySize != 0) return "declares " + name + " as an array of blocks; the runtime binds one";
    const bool material = desc->std140Size == 0;
    const uint32_t bound = material ? declared_.materialBlockBytes : desc->std140Size;
    if (material && bound == 0) return "reads " + name + ", but the package declares no parameter block";
    if (b.bytes > bound) {
      std::string why;
      if (material)
        why = declared_.materialBlockBytes > declared_.parameterBytes
                  ? " (its parameters and the preshader's derived members)"
                  : " (its parameters; the package has no preshader program for this variant)";
      return "reads " + name + " as " + std::to_string(b.bytes) + " bytes, but the runtime binds " +
             std::to_string(bound) + why;
    }
    if (!material) return "";
    for (size_t i = 0; i < b.members.size(); ++i) {
      const ReflectedMember& m = b.members[i];
      if (std::string e = materialMember(m); !e.empty())
        return name + " member " + (m.name.empty() ? "#" + std::to_string(i) : "'" + m.name + "'") + " " + e;
    }
    return "";
  }

  // A member of MaterialParams lies on a parameter of the same type and name (when the shader
  // keeps names: a block of another material may agree in every offset and type), on padding no
  // parameter uses (a float: the compiler pads the last parameter vec4 before the derived
  // members), or on derived members the variant's preshader program writes.
  std::string materialMember(const ReflectedMember& m) const {
    const uint64_t end = uint64_t(m.offset) + m.size;
    const std::string where = "(" + toString(m.type) + ", " + bytes(m.offset, end) + ")";
    if (!isParameterType(m.type)) return where + " is not a scalar or vector, which is all parameters are";
    if (m.offset < declared_.parameterBytes) {
      if (end > declared_.parameterBytes)
        return where + " runs past the parameters, which end at byte " + std::to_string(declared_.parameterBytes);
      for (const ProgramInterface::Parameter& p : declared_.parameters) {
        const uint64_t pEnd = uint64_t(p.offset) + 4ull * p.type.components;
        if (pEnd <= m.offset || p.offset >= end) continue;
        if (p.offset != m.offset || !holds(p.type, m.type) || (!m.name.empty() && m.name != p.name))
          return where + " does not match parameter '" + p.name + "' (" + toString(p.type) + ", " +
                 bytes(p.offset, pEnd) + ")";
        return "";
      }
      if (m.type.kind != ScalarKind::Float || m.type.components != 1)
        return where + " lies where the package places no parameter";
      return "";
    }
    if (m.type.kind != ScalarKind::Float) return where + " is a preshaded member, which are floats";
    for (uint64_t word = m.offset / 4; word < (end + 3) / 4; ++word)
      if (word >= declared_.preshadedWords.size() || !declared_.preshadedWords[word])
        return where + " is not written by the variant's preshader program";
    return "";
  }

  std::string sampler(const ReflectedSampler& s) const {
    const ProgramInterface::Sampler* bound = nullptr;
    for (const ProgramInterface::Sampler& d : declared_.samplers)
      if (stage_.bindsByName ? s.name == d.name : (s.set == abi::kTextureSet && s.binding == d.binding)) bound = &d;
    const std::string at =
        stage_.bindsByName ? "" : " (set " + std::to_string(s.set) + " binding " + std::to_string(s.binding) + ")";
    const std::string what = "sampler '" + s.name + "'" + at;
    if (!bound) return "samples " + what + ", which the variant's draws do not bind" + missingTexture(s);
    if (s.arraySize != 0) return "declares " + what + " as an array; the runtime binds one texture there";
    const SamplerShape expected = bound->shadow ? SamplerShape::Shadow2D
                                  : bound->cube ? SamplerShape::Cube
                                                : SamplerShape::Flat2D;
    if (s.shape != expected)
      return "samples " + what + " as " + shapeName(s.shape) + "; the runtime binds " + shapeName(expected) + " there";
    return "";
  }

  // Why a package texture's sampler is unbound: the package does not ship it for this variant.
  std::string missingTexture(const ReflectedSampler& s) const {
    const bool lut = stage_.bindsByName ? s.name == abi::kSpecularLutName
                                        : (s.set == abi::kTextureSet && s.binding == abi::kSpecularLutBinding);
    return lut ? std::string(" (the package ships no ") + abi::kSpecularLutName + " for it)" : "";
  }

  static std::string shapeName(SamplerShape shape) {
    switch (shape) {
      case SamplerShape::Flat2D: return "a 2D texture";
      case SamplerShape::Cube: return "a cube map";
      case SamplerShape::Shadow2D: return "a 2D depth texture with compare";
      case SamplerShape::Other: break;
    }
    return "a texture type other than a float 2D texture or cube map";
  }

  std::string vertexInput(const ReflectedVariable& v) const {
    const std::string what = "vertex input '" + v.name + "'";
    if (!v.location) return "declares " + what + " without a location";
    const bool known =
        std::ranges::any_of(abi::kVertexAttributes, [&](const auto& a) { return a.location == *v.location; }) ||
        std::ranges::any_of(abi::kInstanceAttributes, [&](const auto& a) { return a.location == *v.location; });
    if (known) {
      const abi::VertexAttribute& a = abi::vertexAttribute(*v.location);
      // By name too, where the shader keeps names: an input at another attribute's location reads
      // that attribute (GL assigns locations the shader leaves out).
      const std::string supplies = "a_" + std::string(a.name);
      if (!v.name.empty() && v.name != supplies)
        return "reads " + what + " at location " + std::to_string(a.location) + ", where the runtime supplies " +
               supplies;
      // Float vecN whatever the mesh's packed format: the vertex fetch converts the normalized
      // integers (runtime/vertex_packing.h), so an integer input would read garbage.
      const ValueType supplied{ScalarKind::Float, a.components};
      if (v.type != supplied)
        return "reads " + what + " at location " + std::to_string(a.location) + " as " + toString(v.type) +
               "; the runtime supplies " + supplies + " there as " + toString(supplied);
      return "";
    }
    return "reads " + what + " at location " + std::to_string(*v.location) +
           ", where the runtime supplies no attribute";
  }

  std::string fragmentOutput(const ReflectedVariable& v) const {
    if (declared_.depthOnly)
      return "writes output '" + v.name +
             "'; the shadow pass, which draws the depth-only program, has no colour target";
    const ValueType colour{ScalarKind::Float, 4};
    if (v.location != abi::kForwardColorLocation || v.type != colour)
      return "writes output '" + v.name + "' (" + toString(v.type) +
             (v.location ? " at location " + std::to_string(*v.location) : "") +
             "); the forward pass has one colour target, a vec4 at location " +
             std::to_string(abi::kForwardColorLocation);
    return "";
  }

  const ProgramInterface& declared_;
  const ReflectedStage& stage_;
};

bool samples(const ReflectedStage& stage, const ProgramInterface::Sampler& s) {
  return std::any_of(stage.samplers.begin(), stage.samplers.end(), [&](const ReflectedSampler& r) {
    return stage.bindsByName ? r.name == s.name : (r.set == abi::kTextureSet && r.binding == s.binding);
  });
}

// Vulkan's interface matching: every fragment input a vertex output of the same location and type.
std::string linkageError(const ReflectedStage& vertex, const ReflectedStage& fragment) {
  for (const ReflectedVariable& in : fragment.inputs) {
    if (!in.location) return "the fragment shader declares input '" + in.name + "' without a location";
    const ReflectedVariable* out = nullptr;
    for (const ReflectedVariable& o : vertex.outputs)
      if (o.location == in.location) out = &o;
    const std::string what = "the " + fragment.what + " reads input '" + in.name + "' (" + toString(in.type) +
                             ") at location " + std::to_string(*in.location);
    if (!out) return what + ", which the " + vertex.what + " does not write";
    if (out->type != in.type) return what + ", which the " + vertex.what + " writes as " + toString(out->type);
  }
  return "";
}

}  // namespace

std::string toString(const ValueType& t) {
  std::string s;
  const char* prefix = t.kind == ScalarKind::Int    ? "i"
                       : t.kind == ScalarKind::Uint ? "u"
                       : t.kind == ScalarKind::Bool ? "b"
                                                    : "";
  if (t.kind == ScalarKind::Other) {
    s = "a type other than a number, vector or matrix";
  } else if (t.columns > 1) {
    s = std::string(prefix) + "mat" + std::to_string(t.columns) +
        (t.components != t.columns ? "x" + std::to_string(t.components) : "");
  } else if (t.components == 1) {
    s = t.kind == ScalarKind::Int    ? "int"
        : t.kind == ScalarKind::Uint ? "uint"
        : t.kind == ScalarKind::Bool ? "bool"
                                     : "float";
  } else {
    s = std::string(prefix) + "vec" + std::to_string(t.components);
  }
  return t.arraySize ? s + "[" + std::to_string(t.arraySize) + "]" : s;
}

std::string interfaceError(const ProgramInterface& declared, const std::vector<ReflectedStage>& stages,
                           bool checkLinkage) {
  const std::string prefix = "material '" + declared.material + "' variant " + declared.variant + ": ";
  for (const ReflectedStage& stage : stages)
    if (std::string e = StageCheck(declared, stage).run(); !e.empty()) return prefix + "the " + stage.what + " " + e;
  for (const std::string& name : declared.packageTextures) {
    const auto sampler = std::find_if(declared.samplers.begin(), declared.samplers.end(),
                                      [&](const ProgramInterface::Sampler& s) { return s.name == name; });
    if (sampler == declared.samplers.end() ||
        std::none_of(stages.begin(), stages.end(), [&](const ReflectedStage& s) { return samples(s, *sampler); }))
      return prefix + "the package ships texture '" + name + "' for this variant, which neither shader samples";
  }
  if (checkLinkage) {
    const ReflectedStage* vertex = nullptr;
    const ReflectedStage* fragment = nullptr;
    for (const ReflectedStage& s : stages) {
      if (s.stage == package::Stage::Vertex) vertex = &s;
      if (s.stage == package::Stage::Fragment) fragment = &s;
    }
    if (vertex && fragment)
      if (std::string e = linkageError(*vertex, *fragment); !e.empty()) return prefix + e;
  }
  return "";
}

}  // namespace facet::package
