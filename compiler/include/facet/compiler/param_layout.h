// std140 layout of the "MaterialParams" uniform block, in declaration order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/ir/module.h"

namespace facet::compiler {

struct ParamSlot {
  std::string name;
  ir::Type type;
  uint32_t offset;
  uint32_t size;         // 0: not in the block
  int textureSlot = -1;  // textures: sampler slot i (binding abi::kMaterialTextureBase + i); -1 unused
};

struct ParamLayout {
  std::vector<ParamSlot> slots;
  uint32_t blockSize = 0;  // 0 when the material has no parameters (no block is declared)
};

// std140 (GLSL ES 3.00 §4.3.7 / OpenGL 4.5 §7.6.2.2): scalars align to 4, vec2 to 8, vec3 and
// vec4 to 16; vec3 occupies 12 bytes, so a following float packs into its fourth slot; the
// block size rounds up to 16. tests/compiler/test_shader_abi.cpp checks it against glslang's reflection.
// Parameters the optimised material never reads (Param::used false) get size 0 and no member.
ParamLayout layoutParams(const std::vector<ir::Param>& params);

}  // namespace facet::compiler
