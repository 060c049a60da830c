#pragma once

#include <cstddef>
#include <cstdint>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// One vertex of a Mesh, which backends pack (vertex_packing.h). The defaults are what a mesh without the
// attribute carries: white vertex colour, uv1 = (0, 0), and a tangent along +x with w = +1.
struct Vertex {
  float position[3] = {0, 0, 0};
  float normal[3] = {0, 0, 1};
  float uv0[2] = {0, 0};
  float uv1[2] = {0, 0};
  float color[4] = {1, 1, 1, 1};
  float tangent[4] = {1, 0, 0, 1};
};
static_assert(sizeof(Vertex) == abi::kVertexStride, "Vertex mirrors shader_abi.h's layout");

void appendVertex(Mesh& mesh, const Vertex& v);

// What a backend's uploaded copy of a mesh depends on: sizes and a hash of every vertex and
// index (facet/runtime/content_hash.h). Backends key their mesh buffers by the Mesh's address and upload
// again when this changes, so a mesh edited in place, or a new one at a freed address, is not
// drawn stale. Computed once per distinct mesh per frame, not once per object.
struct MeshIdentity {
  size_t vertexFloats = 0;
  size_t indexCount = 0;
  uint64_t hash = 0;

  static MeshIdentity of(const Mesh& mesh);
  bool operator==(const MeshIdentity&) const = default;
};

// A unit sphere centred at the origin, latitude/longitude tessellated, outward normals, uv0 =
// (longitude, latitude) in [0, 1], uv1 = uv0, analytic tangents along +u (longitude). With
// 64 × 128 segments the flat facets sit at most 1 − cos(π/128) ≈ 3e-4 of the radius inside the
// true sphere.
Mesh makeSphere(int rings = 64, int segments = 128);

}  // namespace facet::runtime
