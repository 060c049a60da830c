#include "facet/runtime/mesh_optimize.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <vector>

namespace facet::runtime {
namespace {

// The cache size the optimiser plans for and the ACMR figure is measured with: meshoptimizer's
// own default, a size that suits the FIFO caches of mobile GPUs' vertex stages.
constexpr unsigned kCacheSize = 16;
// Overdraw ordering may cost this much ACMR (meshoptimizer's recommended 1.05: 5 % more vertex
// shading for fewer pixels shaded twice).
constexpr float kOverdrawThreshold = 1.05f;

bool wellFormed(const Mesh& mesh) {
  if (mesh.vertices.empty() || mesh.vertices.size() % abi::kVertexFloats != 0) return false;
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) return false;
  const size_t vertexCount = mesh.vertices.size() / abi::kVertexFloats;
  return *std::max_element(mesh.indices.begin(), mesh.indices.end()) < vertexCount;
}

}  // namespace

void optimizeMesh(Mesh* mesh) {
  if (!wellFormed(*mesh)) return;
  const size_t vertexCount = mesh->vertices.size() / abi::kVertexFloats;
  const size_t indexCount = mesh->indices.size();
  std::vector<uint32_t> cacheOrder(indexCount);
  meshopt_optimizeVertexCache(cacheOrder.data(), mesh->indices.data(), indexCount, vertexCount);
  meshopt_optimizeOverdraw(mesh->indices.data(), cacheOrder.data(), indexCount, mesh->vertices.data(), vertexCount,
                           abi::kVertexStride, kOverdrawThreshold);
  std::vector<float> fetchOrder(mesh->vertices.size());
  const size_t used = meshopt_optimizeVertexFetch(fetchOrder.data(), mesh->indices.data(), indexCount,
                                                  mesh->vertices.data(), vertexCount, abi::kVertexStride);
  fetchOrder.resize(used * abi::kVertexFloats);
  mesh->vertices = std::move(fetchOrder);
}

double averageCacheMissRatio(const Mesh& mesh) {
  if (!wellFormed(mesh)) return 0;
  return meshopt_analyzeVertexCache(mesh.indices.data(), mesh.indices.size(), mesh.vertices.size() / abi::kVertexFloats,
                                    kCacheSize, 0, 0)
      .acmr;
}

}  // namespace facet::runtime
