// Bounds-checked iteration over the instructions of a SPIR-V module, shared by the passes that
// read raw words (mobile_cost, lower_relaxed_to_quantized). The words may come from a package
// file, so no operand is read past its instruction and no string past its words.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

struct SpirvInstruction {
  size_t offset = 0;  // word index of the instruction in the module
  uint32_t opcode = 0;
  uint32_t count = 0;  // words, including the opcode word
  const uint32_t* words = nullptr;

  // Word i of the instruction (0 is the opcode word), or 0 when the instruction is shorter.
  uint32_t operand(uint32_t i) const { return i < count ? words[i] : 0; }
  // The literal string starting at word `first`, ending at its NUL or the instruction's end.
  std::string literalString(uint32_t first) const {
    std::string s;
    for (uint32_t i = first; i < count; ++i)
      for (int b = 0; b < 4; ++b) {
        char c = char((words[i] >> (8 * b)) & 0xff);
        if (c == '\0') return s;
        s += c;
      }
    return s;
  }
};

// Calls visit(instruction) for each instruction after the 5-word header, in order. False, with
// *error set and nothing visited past the fault, for a module without the SPIR-V magic number
// or with a zero-length or truncated instruction.
template <typename Visit>
bool forEachSpirvInstruction(const std::vector<uint32_t>& module, Visit visit, std::string* error) {
  constexpr uint32_t kMagic = 0x07230203;
  if (module.size() < 5 || module[0] != kMagic) {
    *error = "not a SPIR-V module";
    return false;
  }
  for (size_t i = 5; i < module.size();) {
    SpirvInstruction ins{i, module[i] & 0xffff, module[i] >> 16, &module[i]};
    if (ins.count == 0 || i + ins.count > module.size()) {
      *error = "truncated instruction at word " + std::to_string(i);
      return false;
    }
    visit(ins);
    i += ins.count;
  }
  return true;
}

}  // namespace facet::compiler
