#include "facet/lint/shadow_precision.h"

#include <algorithm>
#include <map>
#include <set>

#include <spirv-tools/libspirv.h>
#include <spirv/unified1/spirv.h>

namespace facet::lint {
namespace {

// One stage's SPIR-V as a graph of which ids each id's value is read from.
struct Module {
  std::map<uint32_t, std::vector<uint32_t>> reads;
  std::set<uint32_t> relaxed;
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> locations;  // interface variable -> Location
  std::set<uint32_t> inputs, outputs;      // Input and Output variables
  std::vector<uint32_t> compareOperands;   // coordinates and references of depth compares
  uint32_t compares = 0;
  // Calls, resolved once every function is known: a call's value is its callee's return values,
  // a parameter's the argument passed to it.
  struct Call {
    uint32_t result, function;
    std::vector<uint32_t> arguments;
  };
  std::vector<Call> calls;
  std::map<uint32_t, std::vector<uint32_t>> parameters, returns;
  uint32_t function = 0;                   // the function being parsed
  std::map<uint32_t, uint32_t> chainBase;  // access chain -> the pointer it indexes
  std::set<uint32_t> loads;                // OpLoad results
};

bool isDepthCompare(uint32_t opcode) {
  switch (opcode) {
    case SpvOpImageSampleDrefImplicitLod:
    case SpvOpImageSampleDrefExplicitLod:
    case SpvOpImageSampleProjDrefImplicitLod:
    case SpvOpImageSampleProjDrefExplicitLod:
    case SpvOpImageDrefGather:
    case SpvOpImageSparseSampleDrefImplicitLod:
    case SpvOpImageSparseSampleDrefExplicitLod:
    case SpvOpImageSparseSampleProjDrefImplicitLod:
    case SpvOpImageSparseSampleProjDrefExplicitLod:
    case SpvOpImageSparseDrefGather: return true;
    default: return false;
  }
}

uint32_t word(const spv_parsed_instruction_t* in, uint16_t operand) { return in->words[in->operands[operand].offset]; }

spv_result_t parseInstruction(void* user, const spv_parsed_instruction_t* in) {
  Module& m = *static_cast<Module*>(user);
  const uint32_t op = in->opcode;
  std::vector<uint32_t> ids;
  for (uint16_t i = 0; i < in->num_operands; ++i)
    if (in->operands[i].type == SPV_OPERAND_TYPE_ID) ids.push_back(word(in, i));
  switch (op) {
    case SpvOpName:
      m.names[word(in, 0)] = reinterpret_cast<const char*>(in->words + in->operands[1].offset);
      return SPV_SUCCESS;
    case SpvOpDecorate:
      if (word(in, 1) == SpvDecorationRelaxedPrecision) m.relaxed.insert(word(in, 0));
      if (word(in, 1) == SpvDecorationLocation && in->num_operands > 2) m.locations[word(in, 0)] = word(in, 2);
      return SPV_SUCCESS;
    case SpvOpVariable:
      if (word(in, 2) == SpvStorageClassInput) m.inputs.insert(in->result_id);
      if (word(in, 2) == SpvStorageClassOutput) m.outputs.insert(in->result_id);
      break;
    case SpvOpFunction: m.function = in->result_id; break;
    case SpvOpLoad: m.loads.insert(in->result_id); break;
    case SpvOpFunctionParameter: m.parameters[m.function].push_back(in->result_id); break;
    case SpvOpReturnValue: m.returns[m.function].push_back(ids.at(0)); return SPV_SUCCESS;
    case SpvOpFunctionCall:
      m.calls.push_back({in->result_id, ids.at(0), std::vector<uint32_t>(ids.begin() + 1, ids.end())});
      break;
    case SpvOpAccessChain:
    case SpvOpInBoundsAccessChain:
    case SpvOpPtrAccessChain:
    case SpvOpInBoundsPtrAccessChain: m.chainBase[in->result_id] = ids.at(0); break;
    case SpvOpStore: {
      // A stored value is what the pointer, and the variable under it, later load.
      uint32_t pointer = ids.at(0);
      m.reads[pointer].push_back(ids.at(1));
      while (m.chainBase.count(pointer)) {
        pointer = m.chainBase[pointer];
        m.reads[pointer].push_back(ids.at(1));
      }
      return SPV_SUCCESS;
    }
    default: break;
  }
  if (isDepthCompare(op)) {
    // Operands: result type, result, sampled image, coordinate, reference.
    ++m.compares;
    m.compareOperands.push_back(word(in, 3));
    m.compareOperands.push_back(word(in, 4));
  }
  if (in->result_id != 0) {
    std::vector<uint32_t>& r = m.reads[in->result_id];
    r.insert(r.end(), ids.begin(), ids.end());
  }
  return SPV_SUCCESS;
}

bool parse(std::span<const uint32_t> words, Module* m, std::string* error) {
  spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
  spv_diagnostic diagnostic = nullptr;
  const spv_result_t result =
      spvBinaryParse(context, m, words.data(), words.size(), nullptr, parseInstruction, &diagnostic);
  if (result != SPV_SUCCESS)
    *error = "cannot parse the SPIR-V: " + std::string(diagnostic ? diagnostic->error : "unknown error");
  spvDiagnosticDestroy(diagnostic);
  spvContextDestroy(context);
  if (result != SPV_SUCCESS) return false;
  for (const Module::Call& call : m->calls) {
    std::vector<uint32_t>& r = m->reads[call.result];
    const std::vector<uint32_t>& returned = m->returns[call.function];
    r.insert(r.end(), returned.begin(), returned.end());
    const std::vector<uint32_t>& parameters = m->parameters[call.function];
    for (size_t i = 0; i < std::min(parameters.size(), call.arguments.size()); ++i)
      m->reads[parameters[i]].push_back(call.arguments[i]);
  }
  return true;
}

// The surface normal is mediump by the precision policy and reaches the coordinate only as the
// normal offset's direction (templates/forward.vert.glsl): unit length, its fp16 rounding (2^-11
// of each component) moves the lookup by at most 2^-11 of the offset, which is at most 64 texels
// (shadows.normalBias): 1/32 texel. The variable and its loads are not followed.
bool isNormalOffsetDirection(Module& m, uint32_t id) {
  auto isNormal = [&](uint32_t v) {
    auto name = m.names.find(v);
    return name != m.names.end() && name->second == "v_normal";
  };
  if (isNormal(id)) return true;
  const std::vector<uint32_t>& from = m.reads[id];
  return m.loads.count(id) && from.size() == 1 && isNormal(from[0]);
}

// Every id the seeds are computed from, the seeds included.
std::set<uint32_t> trace(Module& m, std::vector<uint32_t> pending) {
  std::set<uint32_t> seen;
  while (!pending.empty()) {
    const uint32_t id = pending.back();
    pending.pop_back();
    if (isNormalOffsetDirection(m, id) || !seen.insert(id).second) continue;
    for (uint32_t from : m.reads[id]) pending.push_back(from);
  }
  return seen;
}

std::vector<std::string> relaxedAmong(const Module& m, const std::set<uint32_t>& ids) {
  std::set<std::string> found;
  for (uint32_t id : ids) {
    if (!m.relaxed.count(id)) continue;
    auto name = m.names.find(id);
    found.insert(name != m.names.end() && !name->second.empty() ? name->second : "%" + std::to_string(id));
  }
  return {found.begin(), found.end()};
}

}  // namespace

bool analyseShadowPrecision(std::span<const uint32_t> vertex, std::span<const uint32_t> fragment, ShadowPrecision* out,
                            std::string* error) {
  *out = {};
  Module f, v;
  if (!parse(fragment, &f, error) || !parse(vertex, &v, error)) return false;
  out->compares = f.compares;
  const std::set<uint32_t> fragmentIds = trace(f, f.compareOperands);
  // The varyings among them, by location: the vertex stage's outputs there are the start of the chain.
  std::set<uint32_t> varyings;
  for (uint32_t id : fragmentIds)
    if (f.inputs.count(id) && f.locations.count(id)) varyings.insert(f.locations[id]);
  std::vector<uint32_t> written;
  for (uint32_t id : v.outputs)
    if (v.locations.count(id) && varyings.count(v.locations[id])) written.push_back(id);
  const std::set<uint32_t> vertexIds = trace(v, written);
  out->feeding = uint32_t(fragmentIds.size() + vertexIds.size());
  out->fragmentRelaxed = relaxedAmong(f, fragmentIds);
  out->vertexRelaxed = relaxedAmong(v, vertexIds);
  return true;
}

}  // namespace facet::lint
