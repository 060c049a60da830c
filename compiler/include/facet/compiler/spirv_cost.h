// Static cost of a shader stage, read from its optimised SPIR-V (DESIGN.md, "Measuring"):
// what a mobile GPU's scalar ALUs, special-function units and texture units will be asked for.
// Static counts, not timings: branches are counted once, loops once per body.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

struct StageCost {
  uint32_t aluOps = 0;            // arithmetic, logic, comparison, conversion instructions
  uint32_t scalarAluOps = 0;      // the same, weighted by result components (scalar-ALU cost)
  uint32_t transcendentalOps = 0; // exp/log/pow/sin/cos/sqrt/inversesqrt (incl. inside normalize, length)
  uint32_t divisions = 0;         // float and integer divisions and remainders
  uint32_t textureSamples = 0;    // sample, fetch and gather instructions
  uint32_t varyingComponents = 0; // scalar components of the stage's non-built-in inputs
  uint32_t relaxedOps = 0;        // ALU + transcendental results decorated RelaxedPrecision (mediump)

  double relaxedPercent() const {
    uint32_t all = aluOps + transcendentalOps;
    return all == 0 ? 0.0 : 100.0 * relaxedOps / all;
  }
};

// Counts instructions inside function bodies. Returns false with *error on malformed SPIR-V.
bool analyseSpirvCost(const std::vector<uint32_t>& words, StageCost* cost, std::string* error);

}  // namespace facet::compiler
