// What a material variant's draws bind, from its package, and the one check of a shader's own
// interface against it. A package is code the app did not build: its tables may declare one
// interface (a 32-byte parameter block, no specular table) while its shaders read another (64
// bytes, a table at binding 1), and a driver draws anyway, reading past the buffer or an unbound
// texture. So each shader's interface is reflected — SPIR-V by checkVariant (facet/package/checks.h) when
// the runtime core decodes a variant, a linked GLSL ES program by the GL backend before its first
// draw — and compared with the package's here (docs/security.md, "What a package can and cannot do").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/package/package.h"

namespace facet::package {

// A value as a shader declares it: a block member, a stage input or output.
enum class ScalarKind : uint8_t { Float, Int, Uint, Bool, Other };
struct ValueType {
  ScalarKind kind = ScalarKind::Other;
  uint32_t components = 1;  // vector width, 1..4
  uint32_t columns = 1;     // matrices: columns of `components` rows
  uint32_t arraySize = 0;   // 0: not an array
  bool operator==(const ValueType&) const = default;
};
std::string toString(const ValueType& type);  // "float", "vec3", "ivec2", "mat4", "vec4[9]"

// The interface one variant's draws bind (the package's tables, read by variantInterface).
struct ProgramInterface {
  std::string material;
  std::string variant;
  // "MaterialParams": bytes a draw binds (the parameters, plus the preshader's derived members for
  // a variant with a program), 0 when there is no block.
  uint32_t materialBlockBytes = 0;
  uint32_t parameterBytes = 0;  // the block's first bytes: the parameters (MaterialInfo::paramBlockSize)
  struct Parameter {
    std::string name;
    uint32_t offset = 0;
    ValueType type;
  };
  std::vector<Parameter> parameters;  // the parameters with bytes in the block
  // Per 4-byte word of the block: written by the variant's preshader program (derived members).
  std::vector<bool> preshadedWords;
  struct Sampler {
    std::string name;      // the GLSL ES sampler uniform
    uint32_t binding = 0;  // Vulkan: set abi::kTextureSet; GL: texture unit
    bool cube = false;
    bool shadow = false;  // a depth texture with compare (the shadow atlas)
  };
  std::vector<Sampler> samplers;  // every sampler a draw of the variant binds
  bool shadowReceiver = false;    // draws bind ShadowUniforms (a .sh or .sp1 variant)
  bool depthOnly = false;         // the shadow pass's depth-only program: no colour target, no frame textures
  // Textures the package ships for this variant (section TEXS), by sampler name: some stage
  // samples each, as the package says.
  std::vector<std::string> packageTextures;
};

// One shader's (or, for GL, a linked program's) interface as its reflection gives it.
struct ReflectedMember {
  std::string name;  // "" when the module carries no names
  uint32_t offset = 0;
  uint32_t size = 0;  // bytes
  ValueType type;
};
struct ReflectedBlock {
  std::string name;               // block type name, e.g. "MaterialParams"
  uint32_t set = 0, binding = 0;  // Vulkan; unused when the stage binds by name (GL)
  uint32_t bytes = 0;             // the block's size as the shader declares it
  uint32_t arraySize = 0;         // 0: one block
  std::vector<ReflectedMember> members;
};
// Other: 3D, arrayed, multisampled, integer, or a depth-compare type other than a 2D one.
enum class SamplerShape : uint8_t { Flat2D, Cube, Shadow2D, Other };
struct ReflectedSampler {
  std::string name;
  uint32_t set = 0, binding = 0;  // Vulkan; unused when the stage binds by name (GL)
  SamplerShape shape = SamplerShape::Other;
  uint32_t arraySize = 0;
};
struct ReflectedVariable {
  std::string name;
  std::optional<uint32_t> location;  // nullopt: no Location (SPIR-V) or -1 (GL)
  ValueType type;
};
struct ReflectedStage {
  // The stage whose checks apply (vertex inputs, fragment outputs); nullopt for what a GL
  // context without program interface queries cannot attribute to one stage.
  std::optional<package::Stage> stage;
  std::string what;          // names it in messages: "fragment shader (SPIR-V)"
  bool bindsByName = false;  // GLSL ES: blocks and samplers are found by name, not by set/binding
  std::vector<ReflectedBlock> blocks;
  std::vector<ReflectedSampler> samplers;
  std::vector<ReflectedVariable> inputs;   // user-defined, no built-ins
  std::vector<ReflectedVariable> outputs;  // user-defined, no built-ins
  std::vector<std::string> unsupported;    // what the runtime binds nothing for ("storage buffer 'x'")
};

// "" when the stages' interfaces agree with `declared`; else "material 'M' variant V: the
// <stage> shader (<code>) ..." saying what differs. Checks each stage's blocks (ABI set and
// binding, sizes within what the runtime binds, MaterialParams members at the parameters' offsets
// with their types or in preshaded words), samplers (one the draws bind, 2D or cube as bound),
// resources the runtime never binds, vertex inputs against the ABI's vertex stream and fragment
// outputs against the one colour target; then that every texture the package ships for the
// variant is sampled; then, when `checkLinkage` (SPIR-V: GL's linker does this), that each
// fragment input is a vertex output of the same location and type.
std::string interfaceError(const ProgramInterface& declared, const std::vector<ReflectedStage>& stages,
                           bool checkLinkage);

}  // namespace facet::package
