// `matc lint`'s shadow-precision rule (docs/lint.md): a shadow receiver's atlas coordinate and
// compare depth stay highp in every tier (docs/shadows.md, "Filters per tier": an atlas coordinate
// needs steps of 1/8192, fp16 has 1/2048 near 1; a D16 depth 1/65536). Read from a variant's
// SPIR-V, where mediump is the RelaxedPrecision decoration: every value on the way to a depth-
// compare sample's coordinate or reference (OpImage*Dref*) in the fragment stage, followed back
// through loads, stores, calls and the varyings it reads into the vertex stage that writes them.
// One mediump value is allowed on the way: the surface normal (`v_normal`) that gives the normal
// offset its direction, whose fp16 rounding moves the lookup by at most 1/32 texel.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace facet::lint {

struct ShadowPrecision {
  uint32_t compares = 0;  // depth-compare samples of the fragment stage
  uint32_t feeding = 0;   // ids on the way to their coordinates and references, both stages
  // Those of them decorated RelaxedPrecision, by stage: names where the SPIR-V has them (OpName),
  // else %id; sorted, each once.
  std::vector<std::string> vertexRelaxed, fragmentRelaxed;
};

// Fails (false, *error) only on SPIR-V that SPIRV-Tools cannot parse.
bool analyseShadowPrecision(std::span<const uint32_t> vertex, std::span<const uint32_t> fragment, ShadowPrecision* out,
                            std::string* error);

}  // namespace facet::lint
