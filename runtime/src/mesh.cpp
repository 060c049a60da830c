#include "facet/runtime/mesh.h"

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "facet/runtime/content_hash.h"

namespace facet::runtime {

void appendVertex(Mesh& mesh, const Vertex& v) {
  float f[abi::kVertexFloats];
  std::memcpy(f, &v, sizeof f);  // Vertex is the stream's floats in order (static_assert in mesh.h)
  mesh.vertices.insert(mesh.vertices.end(), f, f + abi::kVertexFloats);
}

namespace {

// Triangles of a (rows + 1) × (columns + 1) grid of vertices from `base` on, row after row: the
// quad at (row r, column c) as (a, b, a+1) and (a+1, b, b+1), b the vertex below a. They wind
// counter-clockwise seen from the side cross(∂P/∂v, ∂P/∂u) points to: the outside, for the sphere
// (v southwards, u along longitude) and for appendGrid's faces (v down, u right).
void appendGridIndices(Mesh& mesh, uint32_t base, int rows, int columns) {
  const uint32_t stride = uint32_t(columns + 1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      uint32_t a = base + uint32_t(r) * stride + uint32_t(c), b = a + stride;
      mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
}

// A flat unit square centred at `centre`, facing n = cross(right, up), of segments × segments
// quads: uv0 = uv1 = (0, 0) at its top-left corner (as a viewer facing it sees it), u along
// `right`, v down (along −up), as images are stored (glTF's UV convention). The tangent is ∂P/∂u =
// right; ∂P/∂v = −up = −cross(n, right), so the bitangent sign w is −1 (mesh.h's convention).
void appendGrid(Mesh& mesh, glm::vec3 centre, glm::vec3 right, glm::vec3 up, int segments) {
  const glm::vec3 n = glm::cross(right, up);
  const auto base = uint32_t(mesh.vertices.size() / abi::kVertexFloats);
  for (int row = 0; row <= segments; ++row) {
    for (int column = 0; column <= segments; ++column) {
      const float u = float(column) / float(segments), v = float(row) / float(segments);
      const glm::vec3 p = centre + (u - 0.5f) * right + (0.5f - v) * up;
      appendVertex(mesh,
                   {{p.x, p.y, p.z}, {n.x, n.y, n.z}, {u, v}, {u, v}, {1, 1, 1, 1}, {right.x, right.y, right.z, -1}});
    }
  }
  appendGridIndices(mesh, base, segments, segments);
}

}  // namespace

MeshIdentity MeshIdentity::of(const Mesh& mesh) {
  MeshIdentity id;
  id.vertexFloats = mesh.vertices.size();
  id.indexCount = mesh.indices.size();
  id.hash = hashBytes(mesh.vertices.data(), mesh.vertices.size() * sizeof(float));
  id.hash = hashBytes(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t), id.hash);
  return id;
}

Mesh makeSphere(int rings, int segments) {
  Mesh mesh;
  const double pi = 3.14159265358979323846;
  for (int r = 0; r <= rings; ++r) {
    double v = double(r) / rings;
    double theta = v * pi;  // from +y (north pole) down
    for (int s = 0; s <= segments; ++s) {
      double u = double(s) / segments;
      double phi = u * 2.0 * pi;
      float x = float(std::sin(theta) * std::cos(phi));
      float y = float(std::cos(theta));
      float z = float(-std::sin(theta) * std::sin(phi));
      // ∂P/∂u points along (−sin φ, 0, −cos φ) (also at the poles, as a limit). ∂P/∂v points
      // south (v grows with θ), and cross(n, t) points north, so the bitangent sign w is −1.
      Vertex vertex{{x, y, z},
                    {x, y, z},
                    {float(u), float(v)},
                    {float(u), float(v)},
                    {1, 1, 1, 1},
                    {float(-std::sin(phi)), 0.0f, float(-std::cos(phi)), -1.0f}};
      appendVertex(mesh, vertex);
    }
  }
  appendGridIndices(mesh, 0, rings, segments);
  return mesh;
}

Mesh makePlane(int segments) {
  Mesh mesh;
  appendGrid(mesh, {0, 0, 0}, {1, 0, 0}, {0, 0, -1}, segments);
  return mesh;
}

Mesh makeBox(int segments) {
  Mesh mesh;
  // Each face's (right, up) as a viewer outside it sees them: sides upright (+y up), the top with
  // −z up (the plane's orientation), the bottom with +z up.
  const glm::vec3 faces[6][2] = {
      {{0, 0, -1}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{1, 0, 0}, {0, 0, -1}},  // +x, −x, +y
      {{1, 0, 0}, {0, 0, 1}},  {{1, 0, 0}, {0, 1, 0}}, {{-1, 0, 0}, {0, 1, 0}},  // −y, +z, −z
  };
  for (const auto& [right, up] : faces) appendGrid(mesh, 0.5f * glm::cross(right, up), right, up, segments);
  return mesh;
}

}  // namespace facet::runtime
