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

// A unit square in the xz plane, x and z in [−0.5, 0.5], facing +y: normal +y, uv0 = uv1 = (x +
// 0.5, z + 0.5) (seen from above with −z up, the image reads upright), tangent +x, w = −1. It is
// a grid of segments² quads, not two triangles, because the mid and low tiers light diffuse per
// vertex (forward.vert.glsl) and interpolate it linearly over each triangle. A point light at
// height h over the plane gives irradiance f ∝ h / (h² + r²)^(3/2), whose curvature is largest
// under the light, |f''| = 3 f / h² in every direction; linear interpolation over a triangle errs
// there by |f''| R² / 2, R its circumradius, Δ/√2 for the grid's right triangles of side Δ: (3/4)
// (Δ/h)² of the peak. Under 5 % needs Δ ≤ h/4: 64 segments keep a 20 m ground (Δ = 0.31 m) within
// it for lights 1.25 m or more above it, for 4225 vertices (half the sphere's).
Mesh makePlane(int segments = 64);

// A unit cube, each coordinate in [−0.5, 0.5], flat-shaded: each face its own segments² grid
// (as makePlane) with its outward normal, its tangent along the face's u and w = −1, and uv0 =
// uv1 covering [0, 1]² (side faces upright with +y up, the top as makePlane, the bottom with +z
// up). 16 segments a face keep the per-vertex error above under 5 % for a 5 m face and lights
// 1.25 m or more from it.
Mesh makeBox(int segments = 16);

}  // namespace facet::runtime
