// Meshes reordered for the GPU once, when a scene loads them (built-in and glTF meshes,
// runtime/scene_frame.cpp), with meshoptimizer (Debian's libmeshoptimizer): triangles for the
// post-transform vertex cache, then for overdraw, then vertices in first-use order for vertex
// fetch. The triangles and their vertices are unchanged, only their order (and vertices no
// triangle uses are dropped); winding is kept.
#pragma once

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// Reorders `mesh` in place. A mesh the backends would refuse (partial vertices, indices out of
// range, no whole triangles) is left as it is, for the backend to report.
void optimizeMesh(Mesh* mesh);

// Average cache miss ratio: vertex shader invocations per triangle through a 16-entry FIFO
// post-transform cache (meshopt_analyzeVertexCache; 0.5 is the ideal of a large regular grid,
// 3 the worst). 0 for a mesh with no triangles or one the backends would refuse.
double averageCacheMissRatio(const Mesh& mesh);

}  // namespace facet::runtime
