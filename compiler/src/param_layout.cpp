#include "facet/compiler/param_layout.h"

namespace facet::compiler {

ParamLayout layoutParams(const std::vector<ir::Param>& params) {
  ParamLayout layout;
  uint32_t offset = 0;
  int textureSlot = 0;
  for (const ir::Param& p : params) {
    if (p.type == ir::Type::Texture2D) {  // a sampler, not block bytes
      layout.slots.push_back({p.name, p.type, 0, 0, p.used ? textureSlot++ : -1});
      continue;
    }
    if (!p.used) {  // nothing reads it: no uniform, no bytes
      layout.slots.push_back({p.name, p.type, 0, 0});
      continue;
    }
    uint32_t n = uint32_t(ir::componentCount(p.type));
    uint32_t align = n == 1 ? 4 : n == 2 ? 8 : 16;
    offset = (offset + align - 1) / align * align;
    layout.slots.push_back({p.name, p.type, offset, 4 * n});
    offset += 4 * n;
  }
  layout.blockSize = (offset + 15) / 16 * 16;
  return layout;
}

}  // namespace facet::compiler
