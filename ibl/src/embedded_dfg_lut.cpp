#include "facet/ibl/embedded_dfg_lut.h"

namespace facet::ibl {

const DfgLut& embeddedDfgLut() {
  static const DfgLut lut = [] {
    DfgLut l;
    l.size = generated::kEmbeddedDfgLutSize;
    const size_t count = size_t(l.size) * size_t(l.size) * 2;
    l.texels.assign(generated::kEmbeddedDfgLutTexels, generated::kEmbeddedDfgLutTexels + count);
    return l;
  }();
  return lut;
}

const SheenLut& embeddedSheenLut() {
  static const SheenLut lut = [] {
    SheenLut l;
    l.size = generated::kEmbeddedDfgLutSize;
    const size_t nodes = size_t(l.size + 2) * size_t(l.size + 2);
    l.albedo.assign(generated::kEmbeddedSheenAlbedo, generated::kEmbeddedSheenAlbedo + nodes);
    return l;
  }();
  return lut;
}

}  // namespace facet::ibl
