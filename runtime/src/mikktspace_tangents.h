// Tangents by MikkTSpace (Morten Mikkelsen's reference implementation, third_party/mikktspace/),
// for glTF primitives that are normal-mapped but carry no TANGENT (glTF 2.0 §3.7.2.1: "client
// implementations SHOULD calculate tangents using default MikkTSpace algorithms").
#pragma once

#include <cstddef>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// Fills in the tangents of the triangles mesh->indices[firstIndex..] (vertices from firstVertex
// on), from positions, normals and UV set `uvSet` (0 or 1). A vertex whose corners get different
// tangents (a UV seam, a mirrored half) is split, so the mesh may grow by up to two vertices per
// triangle. False when MikkTSpace fails (out of memory).
bool generateMikkTSpaceTangents(Mesh* mesh, size_t firstVertex, size_t firstIndex, int uvSet);

}  // namespace facet::runtime
