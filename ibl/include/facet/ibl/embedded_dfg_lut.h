// ibl/embedded_dfg_lut.h
// The split-sum DFG table computed at build time (ibl/tools/write_dfg_table.cpp runs
// generateDfgLut(kDfgLutSize, kDfgLutSamples) and writes it as source), so a process that renders
// reads it instead of spending ~1 s of CPU integrating it (docs/ibl.md). Library
// facet_ibl_embedded_dfg.
#pragma once

#include <cstddef>

#include "facet/ibl/dfg_lut.h"
#include "facet/ibl/sheen_lut.h"

namespace facet::ibl {

namespace generated {
extern const int kEmbeddedDfgLutSize;
extern const float kEmbeddedDfgLutTexels[];
extern const float kEmbeddedSheenAlbedo[];
}  // namespace generated

/// The build-time table, bit for bit generateDfgLut(kDfgLutSize, kDfgLutSamples); made once.
const DfgLut& embeddedDfgLut();
/// The build-time sheen albedo, bit for bit generateSheenLut(kDfgLutSize); made once.
const SheenLut& embeddedSheenLut();

}  // namespace facet::ibl
