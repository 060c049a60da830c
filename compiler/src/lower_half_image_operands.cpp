#include "facet/compiler/lower_half_image_operands.h"

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.h>

#include <map>

#include "spirv_walk.h"

namespace facet::compiler {
namespace {

// Word index (within the instruction) of the image-operands mask, or 0 for an opcode this pass
// does not touch. Before the mask: the sampled image or image (3), the coordinate (4), and for
// the depth-compare samples and the gathers the dref or component (5).
uint32_t maskPosition(uint32_t op) {
  switch (op) {
    case SpvOpImageSampleImplicitLod:
    case SpvOpImageSampleExplicitLod:
    case SpvOpImageSampleProjImplicitLod:
    case SpvOpImageSampleProjExplicitLod:
    case SpvOpImageFetch:
    case SpvOpImageRead: return 5;
    case SpvOpImageSampleDrefImplicitLod:
    case SpvOpImageSampleDrefExplicitLod:
    case SpvOpImageSampleProjDrefImplicitLod:
    case SpvOpImageSampleProjDrefExplicitLod:
    case SpvOpImageGather:
    case SpvOpImageDrefGather: return 6;
    default: return 0;
  }
}

}  // namespace

bool lowerHalfImageOperands(std::vector<uint32_t>* words, std::string* error) {
  const std::vector<uint32_t>& in = *words;
  // Pass 1: float types by width and size, value types, where the functions begin.
  uint32_t float32 = 0;
  std::map<uint32_t, uint32_t> halfSize;       // 16-bit float type id -> components (1 = scalar)
  std::map<uint32_t, uint32_t> float32Vector;  // components -> 32-bit float vector type id
  std::map<uint32_t, uint32_t> typeOf;         // value id -> type id
  size_t firstFunction = in.size();
  bool walked = forEachSpirvInstruction(
      in,
      [&](const SpirvInstruction& ins) {
        auto w = [&](uint32_t i) { return ins.operand(i); };
        if (ins.opcode == SpvOpTypeFloat && w(2) == 16) halfSize[w(1)] = 1;
        if (ins.opcode == SpvOpTypeFloat && w(2) == 32) float32 = w(1);
        if (ins.opcode == SpvOpTypeVector && halfSize.count(w(2))) halfSize[w(1)] = w(3);
        if (ins.opcode == SpvOpTypeVector && w(2) == float32 && float32 != 0) float32Vector[w(3)] = w(1);
        if (ins.opcode == SpvOpFunction && firstFunction == in.size()) firstFunction = ins.offset;
        bool hasResult = false, hasType = false;
        SpvHasResultAndType(SpvOp(ins.opcode), &hasResult, &hasType);
        if (hasResult && hasType && ins.count >= 3) typeOf[w(2)] = w(1);
      },
      error);
  if (!walked) return false;
  if (halfSize.empty()) return true;
  if (float32 == 0) {
    *error = "a module with 16-bit floats but no 32-bit float type";
    return false;
  }

  uint32_t bound = in[3];
  std::vector<uint32_t> newTypes;  // vector types to declare before the first function
  auto float32TypeOf = [&](uint32_t halfType) {
    uint32_t n = halfSize[halfType];
    if (n == 1) return float32;
    auto it = float32Vector.find(n);
    if (it != float32Vector.end()) return it->second;
    uint32_t id = bound++;
    newTypes.insert(newTypes.end(), {(4u << 16) | SpvOpTypeVector, id, float32, n});
    float32Vector[n] = id;
    return id;
  };
  auto isHalf = [&](uint32_t id) {
    auto t = typeOf.find(id);
    return t != typeOf.end() && halfSize.count(t->second) != 0;
  };

  // Pass 2: in front of each image instruction, an OpFConvert per half operand; the operand
  // replaced in that instruction only.
  std::vector<uint32_t> body;  // everything from the first function on
  forEachSpirvInstruction(
      in,
      [&](const SpirvInstruction& ins) {
        if (ins.offset < firstFunction) return;
        std::vector<uint32_t> w(ins.words, ins.words + ins.count);
        const uint32_t mask = maskPosition(ins.opcode);
        if (mask != 0) {
          for (uint32_t i = 4; i < ins.count; ++i) {
            if (i == mask || !isHalf(w[i])) continue;  // the mask is a literal, not an id
            uint32_t fresh = bound++;
            body.insert(body.end(), {(4u << 16) | SpvOpFConvert, float32TypeOf(typeOf[w[i]]), fresh, w[i]});
            w[i] = fresh;
          }
        }
        body.insert(body.end(), w.begin(), w.end());
      },
      error);

  std::vector<uint32_t> out(in.begin(), in.begin() + long(firstFunction));
  out.insert(out.end(), newTypes.begin(), newTypes.end());
  out.insert(out.end(), body.begin(), body.end());
  out[3] = bound;
  *words = std::move(out);
  return true;
}

}  // namespace facet::compiler
