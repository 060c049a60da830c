#include "facet/runtime/mesh.h"

#include <cmath>
#include <cstring>

#include "facet/runtime/content_hash.h"

namespace facet::runtime {

void appendVertex(Mesh& mesh, const Vertex& v) {
  float f[abi::kVertexFloats];
  std::memcpy(f, &v, sizeof f);  // Vertex is the stream's floats in order (static_assert in mesh.h)
  mesh.vertices.insert(mesh.vertices.end(), f, f + abi::kVertexFloats);
}

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
  const uint32_t stride = uint32_t(segments + 1);
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      uint32_t a = uint32_t(r) * stride + uint32_t(s), b = a + stride;
      mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return mesh;
}

}  // namespace facet::runtime
