#include "facet/runtime/preshader.h"

#include <array>
#include <cmath>
#include <cstring>

namespace facet::runtime {

bool runPreshader(std::span<const package::PreshaderOp> ops, uint32_t paramBlockSize, std::span<uint8_t> block,
                  std::string* error) {
  if (block.size() > package::kMaxParamBlockBytes) {
    *error = "a preshaded block of " + std::to_string(block.size()) + " bytes; the limit is " +
             std::to_string(package::kMaxParamBlockBytes);
    return false;
  }
  if (std::string e = package::preshaderError(ops, paramBlockSize, uint32_t(block.size())); !e.empty()) {
    *error = e;
    return false;
  }
  using Vec4 = std::array<float, 4>;
  std::array<Vec4, package::kPreshaderRegisters> r{};
  for (const package::PreshaderOp& op : ops) {
    Vec4& d = r[op.dst];
    const Vec4 a = r[op.a], b = r[op.b];  // copies: dst may alias an operand
    switch (op.code) {
      case package::PreshaderOpcode::LoadParam:
        d = {};
        std::memcpy(d.data(), block.data() + op.offset, 4 * op.count);
        if (op.count == 1) d = {d[0], d[0], d[0], d[0]};  // scalars are broadcast
        break;
      case package::PreshaderOpcode::Constant: d = op.k; break;
      case package::PreshaderOpcode::Add:
        for (size_t i = 0; i < 4; ++i) d[i] = a[i] + b[i];
        break;
      case package::PreshaderOpcode::Sub:
        for (size_t i = 0; i < 4; ++i) d[i] = a[i] - b[i];
        break;
      case package::PreshaderOpcode::Mul:
        for (size_t i = 0; i < 4; ++i) d[i] = a[i] * b[i];
        break;
      case package::PreshaderOpcode::Clamp:
        // fmax returns the number when one side is NaN: a NaN parameter becomes the lower bound.
        for (size_t i = 0; i < 4; ++i) d[i] = std::fmin(std::fmax(a[i], op.k[0]), op.k[1]);
        break;
      case package::PreshaderOpcode::Swizzle:
        for (size_t i = 0; i < 4; ++i) d[i] = a[(op.offset >> (2 * i)) & 3];
        break;
      case package::PreshaderOpcode::Store: std::memcpy(block.data() + op.offset, a.data(), 4 * op.count); break;
      // IEEE fp32 as the shader's highp: x / 0 is ±inf, sqrt of a negative NaN (GLSL leaves both
      // undefined; the compiler only emits them where the material's own expression has them).
      case package::PreshaderOpcode::Div:
        for (size_t i = 0; i < 4; ++i) d[i] = a[i] / b[i];
        break;
      case package::PreshaderOpcode::Sqrt:
        for (size_t i = 0; i < 4; ++i) d[i] = std::sqrt(a[i]);
        break;
    }
  }
  return true;
}

}  // namespace facet::runtime
