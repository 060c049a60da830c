// PRSH section (format 1.3): the preshader programs, and the checks that make a program from an
// untrusted package safe to run (package.h, preshaderError).
#include <algorithm>
#include <bit>
#include <cmath>
#include <set>

#include "sections.h"

namespace facet::package {

const char* toString(PreshaderOpcode code) {
  switch (code) {
    case PreshaderOpcode::LoadParam: return "load_param";
    case PreshaderOpcode::Constant: return "constant";
    case PreshaderOpcode::Add: return "add";
    case PreshaderOpcode::Sub: return "sub";
    case PreshaderOpcode::Mul: return "mul";
    case PreshaderOpcode::Clamp: return "clamp";
    case PreshaderOpcode::Swizzle: return "swizzle";
    case PreshaderOpcode::Store: return "store";
    case PreshaderOpcode::Div: return "div";
    case PreshaderOpcode::Sqrt: return "sqrt";
  }
  return "?";
}

bool usesPreshaderDivision(std::span<const PreshaderOp> ops) {
  return std::any_of(ops.begin(), ops.end(), [](const PreshaderOp& op) {
    return op.code == PreshaderOpcode::Div || op.code == PreshaderOpcode::Sqrt;
  });
}

std::string preshaderError(std::span<const PreshaderOp> ops, uint32_t paramBlockSize, uint32_t blockSize) {
  if (ops.size() > kMaxPreshaderOps)
    return "a preshader program of " + std::to_string(ops.size()) + " ops; the limit is " +
           std::to_string(kMaxPreshaderOps);
  if (paramBlockSize > blockSize) return "the parameters do not fit in the preshaded block";
  for (size_t i = 0; i < ops.size(); ++i) {
    const PreshaderOp& op = ops[i];
    const std::string what = "preshader op " + std::to_string(i);
    if (uint8_t(op.code) > kLastPreshaderOpcode) return what + " has unknown opcode " + std::to_string(int(op.code));
    const std::string name = what + " (" + toString(op.code) + ")";
    if (op.dst >= kPreshaderRegisters || op.a >= kPreshaderRegisters || op.b >= kPreshaderRegisters)
      return name + " names a register beyond r" + std::to_string(kPreshaderRegisters - 1);
    for (float k : op.k)
      if (!std::isfinite(k)) return name + " has a constant that is not finite";
    const bool load = op.code == PreshaderOpcode::LoadParam, store = op.code == PreshaderOpcode::Store;
    if (load || store) {
      if (op.count < 1 || op.count > 4) return name + " moves " + std::to_string(op.count) + " components (1..4)";
      if (op.offset % 4 != 0) return name + " has byte offset " + std::to_string(op.offset) + ", not a multiple of 4";
      // 64-bit sum: offset and count are untrusted u32s.
      const uint64_t end = uint64_t(op.offset) + 4ull * op.count;
      if (load && end > paramBlockSize)
        return name + " reads bytes " + std::to_string(op.offset) + ".." + std::to_string(end) +
               ", outside the parameters (" + std::to_string(paramBlockSize) + " bytes)";
      if (store && (op.offset < paramBlockSize || end > blockSize))
        return name + " writes bytes " + std::to_string(op.offset) + ".." + std::to_string(end) +
               ", outside the derived members (bytes " + std::to_string(paramBlockSize) + ".." +
               std::to_string(blockSize) + ")";
    } else if (op.code == PreshaderOpcode::Swizzle) {
      if (op.offset > 0xff) return name + " has selector " + std::to_string(op.offset) + " (8 bits)";
    }
  }
  return "";
}

std::string preshaderSemanticError(const MaterialInfo& material, const Preshader& preshader) {
  if (preshader.programs.empty()) return "";
  if (preshader.blockSize <= material.paramBlockSize)
    return "the preshaded block is " + std::to_string(preshader.blockSize) +
           " bytes, not above the parameter block's " + std::to_string(material.paramBlockSize);
  for (size_t i = 0; i < preshader.programs.size(); ++i)
    if (std::string e = preshaderError(preshader.programs[i].ops, material.paramBlockSize, preshader.blockSize);
        !e.empty())
      return "preshader program " + std::to_string(i) + ": " + e;
  return "";
}

namespace detail {

void encodePreshader(ByteWriter& out, const Preshader& preshader) {
  out.u32(preshader.blockSize);
  out.u32(uint32_t(preshader.programs.size()));
  for (const PreshaderProgram& p : preshader.programs) {
    out.u32(uint32_t(p.variants.size()));
    for (uint32_t v : p.variants) out.u32(v);
    out.u32(uint32_t(p.ops.size()));
    for (const PreshaderOp& op : p.ops) {
      out.u8(uint8_t(op.code));
      out.u8(op.dst);
      out.u8(op.a);
      out.u8(op.b);
      out.u32(op.offset);
      out.u32(op.count);
      for (float k : op.k) out.u32(std::bit_cast<uint32_t>(k));
    }
  }
}

void decodePreshader(ByteReader& in, uint64_t variantCount, Preshader& preshader) {
  preshader.blockSize = in.u32();
  if (!in.ok()) return;
  // The block against the parameters, and each op, are meaning: package::semanticError.
  if (preshader.blockSize == 0 || preshader.blockSize % 16 != 0 || preshader.blockSize > kMaxParamBlockBytes)
    return in.fail("the preshaded block is " + std::to_string(preshader.blockSize) +
                   " bytes: it must be a multiple of 16 in 16.." + std::to_string(kMaxParamBlockBytes));
  const uint32_t count = in.count(kMinPreshaderProgramSize, "preshader program count");
  if (!in.ok()) return;
  if (count == 0) return in.fail("a preshader section without programs");
  std::set<uint32_t> seen;
  preshader.programs.reserve(count);
  for (uint32_t i = 0; i < count && in.ok(); ++i) {
    const std::string what = "preshader program " + std::to_string(i);
    PreshaderProgram p;
    const uint32_t users = in.count(kVariantIndexSize, "variant index count");
    p.variants.reserve(users);
    for (uint32_t j = 0; j < users && in.ok(); ++j) {
      const uint32_t v = in.u32();
      if (!in.ok()) return;
      if (v >= variantCount)
        return in.fail(what + " lists variant " + std::to_string(v) + " but the package has " +
                       std::to_string(variantCount) + " variants");
      if (!p.variants.empty() && v <= p.variants.back())
        return in.fail(what + " lists variant " + std::to_string(v) + " after " + std::to_string(p.variants.back()) +
                       " (indices must increase)");
      if (!seen.insert(v).second)
        return in.fail(what + " lists variant " + std::to_string(v) + ", which has a program");
      p.variants.push_back(v);
    }
    const uint32_t opCount = in.count(kPreshaderOpSize, "preshader op count");
    if (!in.ok()) return;
    if (opCount > kMaxPreshaderOps)
      return in.fail(what + " has " + std::to_string(opCount) + " ops; the limit is " +
                     std::to_string(kMaxPreshaderOps));
    p.ops.reserve(opCount);
    for (uint32_t j = 0; j < opCount && in.ok(); ++j) {
      PreshaderOp op;
      const uint8_t code = in.u8();
      op.dst = in.u8();
      op.a = in.u8();
      op.b = in.u8();
      op.offset = in.u32();
      op.count = in.u32();
      for (float& k : op.k) k = std::bit_cast<float>(in.u32());
      // An unknown opcode stays representable (uint8_t enum) and preshaderError names it.
      op.code = PreshaderOpcode(code);
      p.ops.push_back(op);
    }
    preshader.programs.push_back(std::move(p));
  }
  in.expectEnd();
}

}  // namespace detail
}  // namespace facet::package
