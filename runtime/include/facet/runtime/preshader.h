// The preshader's interpreter: runs a package's program (package::PreshaderProgram, format 1.3)
// over an instance's "MaterialParams" bytes, reading the parameters and writing the derived
// members after them. It knows ops, not shading: what the ops compute is the compiler's
// (compiler/preshader.h).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "facet/package/package.h"

namespace facet::runtime {

// Checks the program against the block (package::preshaderError: a program from an untrusted
// package or an app), then runs it in fp32. False with *error, the block unchanged, when the
// check fails. NaN or infinite parameters are computed like any other value (IEEE fp32, no
// undefined behaviour); a Clamp turns NaN into its lower bound.
bool runPreshader(std::span<const package::PreshaderOp> ops, uint32_t paramBlockSize, std::span<uint8_t> block,
                  std::string* error);

}  // namespace facet::runtime
